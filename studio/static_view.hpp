#pragma once
// `tendril view`: one self-contained HTML file (the built web/dist/view page
// with its script and style inlined, and the data) showing a model, its
// growth timeline and its colour maps, to send to someone; no server.
#include <string>

namespace tendril::studio {

// input: an output folder (its journal.txt, else model.xml, else the one
// *.xml in it), a model database (.xml) or a journal. A journal gives a
// timeline of at most max_entries models after its productions, spread
// evenly, the last one always included. Throws with a message naming the
// input or the page file at fault.
std::string static_view(const std::string& input, const std::string& web_dir, std::size_t max_entries = 120);

}  // namespace tendril::studio
