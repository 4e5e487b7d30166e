#include "util/number_list.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "util/error.hpp"

namespace kerf {

std::vector<float> parseNumberList(const std::string& text, const std::string& option) {
  std::istringstream in(text);
  std::vector<float> numbers;
  std::string item;
  while (std::getline(in, item, ',')) {
    const auto first = item.find_first_not_of(' '), last = item.find_last_not_of(' ');
    const std::string trimmed = first == std::string::npos ? "" : item.substr(first, last - first + 1);
    try {
      std::size_t used = 0;
      numbers.push_back(std::stof(trimmed, &used));
      if (used != trimmed.size() || !std::isfinite(numbers.back())) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw InputError(option + ": \"" + item + "\" is not a finite number");
    }
  }
  return numbers;
}

}  // namespace kerf
