#include "core/io/dropped_attributes.h"

#include <algorithm>
#include <set>
#include <vector>

#include "core/support/quoted_text.h"

namespace gps {

namespace {
// "a", "a and b", "a, b and c".
std::string listed(const std::vector<std::string>& parts) {
  std::string out = parts.empty() ? "" : parts[0];
  for (size_t k = 1; k < parts.size(); ++k) out += (k + 1 == parts.size() ? " and " : ", ") + parts[k];
  return out;
}
}  // namespace

void count_unread_vertex_properties(const std::vector<std::string>& names, size_t count, DroppedAttributes& dropped) {
  static const std::set<std::string> kRead = {"x", "y", "z", "cxx", "cxy", "cxz", "cyy", "cyz", "czz", "corner"};
  // Each kind counted by the properties that lead one (a vertex's normal, colour or texture coordinate
  // each), the rest of its properties dropped with it; a property whose kind no property leads is named.
  struct Kind {
    size_t DroppedAttributes::*counted;
    std::set<std::string> leads, rest;
  };
  static const std::vector<Kind> kKinds = {{&DroppedAttributes::normals, {"nx"}, {"ny", "nz"}},
                                           {&DroppedAttributes::colours,
                                            {"red", "diffuse_red"},
                                            {"green", "blue", "alpha", "diffuse_green", "diffuse_blue"}},
                                           {&DroppedAttributes::texture_coordinates,
                                            {"u", "s", "texture_u", "texture_s"},
                                            {"v", "t", "texture_v", "texture_t"}}};
  const std::set<std::string> present(names.begin(), names.end());
  const auto led = [&](const Kind& kind) {
    return std::any_of(kind.leads.begin(), kind.leads.end(), [&](const std::string& n) { return present.count(n); });
  };
  std::vector<std::string> other;
  for (const std::string& n : names) {
    if (kRead.count(n)) continue;
    const auto kind = std::find_if(kKinds.begin(), kKinds.end(),
                                   [&](const Kind& k) { return k.leads.count(n) || (k.rest.count(n) && led(k)); });
    if (kind == kKinds.end())
      other.push_back(quoted_token(n));
    else if (kind->leads.count(n))
      dropped.*kind->counted += count;
  }
  if (!other.empty() && count > 0) dropped.other.push_back(named_list("vertex property", "vertex properties", other));
}

std::string named_list(const std::string& one, const std::string& many, const std::vector<std::string>& names) {
  if (names.empty()) return "";
  if (names.size() <= kNamesListed) return (names.size() == 1 ? one : many) + " " + listed(names);
  std::vector<std::string> first(names.begin(), names.begin() + kNamesListed - 1);
  first.push_back(std::to_string(names.size() - first.size()) + " more");
  return many + " " + listed(first);
}

std::string dropped_attributes_note(const std::string& source, const DroppedAttributes& dropped) {
  std::vector<std::string> parts;
  const auto count = [&](size_t n, const char* one, const char* many) {
    if (n > 0) parts.push_back(std::to_string(n) + " " + (n == 1 ? one : many));
  };
  count(dropped.texture_coordinates, "texture coordinate", "texture coordinates");
  count(dropped.normals, "normal", "normals");
  count(dropped.colours, "vertex colour", "vertex colours");
  parts.insert(parts.end(), dropped.other.begin(), dropped.other.end());
  if (parts.empty()) return "";
  return source + ": " + listed(parts) +
         " dropped (a covariance mesh keeps positions, Gaussians and creases; normals come from the limit surface)";
}

}  // namespace gps
