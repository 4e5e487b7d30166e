#pragma once
// Comma-separated numbers as the command line and the editor's text fields take them ("1,2.5,-3").
#include <string>
#include <vector>

namespace kerf {

// The finite numbers of `text`; throws InputError naming `option` and the first item that is not one.
std::vector<float> parseNumberList(const std::string& text, const std::string& option);

}  // namespace kerf
