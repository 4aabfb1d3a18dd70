#include "sim/resolution.h"

#include <cctype>
#include <stdexcept>

namespace strata::sim {

void parse_resolution(const std::string& text, uint32_t* width, uint32_t* height) {
  const size_t x = text.find('x');
  auto number = [&](const std::string& part) -> uint32_t {
    if (part.empty() || part.size() > 6) throw std::invalid_argument("");
    for (char c : part)
      if (!std::isdigit(static_cast<unsigned char>(c))) throw std::invalid_argument("");
    return uint32_t(std::stoul(part));
  };
  try {
    if (x == std::string::npos) throw std::invalid_argument("");
    *width = number(text.substr(0, x));
    *height = number(text.substr(x + 1));
  } catch (const std::invalid_argument&) {
    throw std::invalid_argument("res: '" + text + "' is not WxH (for example 512x512)");
  }
}

}  // namespace strata::sim
