// tendril: the command line (`tendril --help`; each subcommand in
// app/NAME_command.cpp).
#include "command_line.hpp"
#include "io/atomic_file.hpp"
#include "io/huge_pages.hpp"

int main(int argc, char** argv) {
  tendril::restart_with_huge_pages(argv);
  tendril::clean_up_outputs_on_signals();
  return tendril::app::run_command_line(argc, argv);
}
