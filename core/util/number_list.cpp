#include "util/number_list.hpp"

#include <sstream>

#include "util/parse_number.hpp"

namespace kerf {

std::vector<float> parseNumberList(const std::string& text, const std::string& option) {
  std::istringstream in(text);
  std::vector<float> numbers;
  std::string item;
  while (std::getline(in, item, ',')) numbers.push_back(parseNumber<float>(item, option));
  return numbers;
}

}  // namespace kerf
