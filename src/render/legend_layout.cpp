#include "legend_layout.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace physltl::render {
namespace {

// `line`'s first `keep` characters, "...", and a ')' for each '(' they leave open.
std::string cut(const std::string& line, std::size_t keep) {
  std::string kept = line.substr(0, keep);
  while (!kept.empty() && kept.back() == ' ') kept.pop_back();
  int open = 0;
  for (char c : kept) open += c == '(' ? 1 : c == ')' ? -1 : 0;
  return kept + (kept.empty() ? "..." : " ...") + std::string(static_cast<std::size_t>(std::max(open, 0)), ')');
}

// Where a line may be cut: before a space that follows a whole word or a closing bracket, so that no name
// and no operator is split.
bool cuttable_at(const std::string& line, std::size_t i) {
  if (i == 0 || i >= line.size() || line[i] != ' ') return false;
  const unsigned char before = static_cast<unsigned char>(line[i - 1]);
  return std::isalnum(before) || before == ')' || before == '_' || before == ':';
}

}  // namespace

std::string fitted_line(const FontAtlas& font, const std::string& line, float room) {
  if (font.width(line) <= room) return line;
  std::string best = cut(line, 0);
  for (std::size_t i = 1; i < line.size(); ++i) {
    if (!cuttable_at(line, i)) continue;
    std::string candidate = cut(line, i);
    if (font.width(candidate) > room) break;  // longer cuts are wider still
    best = std::move(candidate);
  }
  return best;
}

std::vector<std::string> shown_lines(const std::vector<std::string>& lines, int rows) {
  const auto limit = static_cast<std::size_t>(std::max(rows, 1));
  if (lines.size() <= limit) return lines;
  std::vector<std::string> shown(lines.begin(), lines.begin() + static_cast<std::ptrdiff_t>(limit - 1));
  shown.push_back(more_lines(lines.size() - shown.size()));
  return shown;
}

std::string more_lines(std::size_t hidden) { return "... " + std::to_string(hidden) + " more lines"; }

int legend_rows(const FontAtlas& font, int height, float padding) {
  return std::max(kLeastLegendRows, static_cast<int>(std::floor((kLegendHeightShare * static_cast<float>(height) - 2 * padding) / font.line_height())));
}

}  // namespace physltl::render
