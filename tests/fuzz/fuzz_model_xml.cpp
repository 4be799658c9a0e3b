// libFuzzer target: the model database reader (tendril.load) on any bytes.
// It must refuse a bad file with ModelError and never crash, hang or leak;
// what it accepts must save, and load back to the same file.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "io/model_xml.hpp"

using namespace tendril;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string xml(reinterpret_cast<const char*>(data), size);
  Model m;
  SolverSettings s;
  try {
    load_model_xml_string(xml, m, s, "fuzz.xml");
  } catch (const ModelError&) {
    return 0;
  }
  const std::string saved = model_xml_string(m, s);
  Model again;
  SolverSettings s2;
  load_model_xml_string(saved, again, s2, "saved.xml");  // the writer's output is always readable
  if (model_xml_string(again, s2) != saved) std::abort();
  return 0;
}
