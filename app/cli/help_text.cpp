#include "app/cli/help_text.hpp"

namespace fieldlines::cli {

std::string help_row(std::string_view head, std::string_view text, std::size_t margin, std::size_t width) {
  std::string row = "  " + std::string(head);
  row.resize(row.size() + 2 <= margin ? margin : row.size() + 3, ' ');
  std::string out;
  std::size_t start = 0;
  do {
    std::size_t end = text.size();
    if (row.size() + (end - start) > width) {
      end = text.rfind(' ', start + (width > row.size() ? width - row.size() : 0));
      if (end == std::string_view::npos || end <= start) end = text.find(' ', start);
      if (end == std::string_view::npos) end = text.size();
    }
    out += row;
    out += text.substr(start, end - start);
    out += '\n';
    row.assign(margin + 2, ' ');
    start = end < text.size() ? end + 1 : end;
  } while (start < text.size());
  return out;
}

}  // namespace fieldlines::cli
