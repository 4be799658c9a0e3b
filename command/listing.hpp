#pragma once
// The list of commands with their parameters, made from the declarations:
// docs/commands.md is this text (a test compares them) and `tendril
// commands` prints it.
#include <string>

#include "command/command.hpp"

namespace tendril::command {

std::string markdown_listing();
// "cable A B EA EI PRESTRESS LINE_MASS REST_LENGTH": the journal line's form.
std::string journal_form(const Command& c);
// The Lua method that applies c ("" when none does directly).
std::string lua_method(const Command& c);

}  // namespace tendril::command
