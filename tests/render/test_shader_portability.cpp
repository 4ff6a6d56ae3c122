// What the GLSL specification forbids and llvmpipe accepts, checked on the shaders' sources, since the
// tests run on llvmpipe: a read of a `writeonly` buffer (NVIDIA's compiler refuses to link one, and a
// chained assignment `a[i] = a[j] = v` reads a[j]).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace {

// The source without its comments, line breaks kept (so that positions keep their lines).
std::string without_comments(const std::string& source) {
  std::string out;
  for (size_t i = 0; i < source.size(); ++i) {
    if (source.compare(i, 2, "//") == 0) {
      while (i < source.size() && source[i] != '\n') ++i;
      if (i < source.size()) out += '\n';
      continue;
    }
    out += source[i];
  }
  return out;
}

// "line N: ..." for every use of a writeonly buffer's array that is not the whole left side of a plain
// assignment: one that starts a statement (after `;`, `{`, `}`, a condition's `)` or a line break) and
// is followed by `=`, not `==`.
std::vector<std::string> writeonly_reads(const std::string& source) {
  const std::string text = without_comments(source);
  std::vector<std::string> names, found;
  const std::regex declaration(R"(writeonly\s+buffer\s+\w+\s*\{\s*[\w ]+?\s+(\w+)\s*\[\s*\])");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), declaration); it != std::sregex_iterator(); ++it)
    names.push_back((*it)[1]);
  for (const std::string& name : names) {
    const std::regex use("\\b" + name + "\\s*\\[");
    for (auto it = std::sregex_iterator(text.begin(), text.end(), use); it != std::sregex_iterator(); ++it) {
      const size_t at = size_t(it->position());
      if (text.compare(at, name.size(), name) != 0) continue;
      size_t before = at;
      while (before > 0 && (text[before - 1] == ' ' || text[before - 1] == '\t')) --before;
      const char previous = before == 0 ? '\n' : text[before - 1];
      size_t end = at + size_t(it->length()), depth = 1;
      if (text.find_first_not_of(" \t", end) < text.size() && text[text.find_first_not_of(" \t", end)] == ']')
        continue;  // the declaration, `name[]`
      while (end < text.size() && depth > 0) depth += text[end] == '[' ? 1 : text[end] == ']' ? -1 : 0, ++end;
      while (end < text.size() && text[end] == ' ') ++end;
      const bool starts_statement =
          previous == ';' || previous == '{' || previous == '}' || previous == ')' || previous == '\n';
      const bool assigned = end + 1 < text.size() && text[end] == '=' && text[end + 1] != '=';
      if (starts_statement && assigned) continue;
      const long line = 1 + std::count(text.begin(), text.begin() + long(at), '\n');
      found.push_back("line " + std::to_string(line) + ": " + name + " is read");
    }
  }
  return found;
}

TEST(ShaderPortability, NoShaderReadsAWriteonlyBuffer) {
  const std::filesystem::path folder = std::filesystem::path(GPS_TEST_DATA_DIR) / ".." / ".." / "shaders";
  int shaders = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() != ".glsl") continue;
    std::ifstream in(entry.path());
    std::stringstream source;
    source << in.rdbuf();
    ++shaders;
    for (const std::string& read : writeonly_reads(source.str()))
      ADD_FAILURE() << entry.path().filename().string() << ", " << read;
  }
  EXPECT_GT(shaders, 20) << folder;
}

TEST(ShaderPortability, TheCheckFindsReadsAndPassesWrites) {
  const std::string declared =
      "layout(std430, binding = 3) writeonly buffer Limits { vec4 limits[]; };\n"
      "layout(std430, binding = 4) readonly buffer Other { int other[]; };\n";
  EXPECT_TRUE(writeonly_reads(declared + "void main() {\n  limits[2 * i] = vec4(0.0);\n"
                                         "  if (other[i] == 0) limits[i + 1] = vec4(1.0);  // limits[i] read\n"
                                         "  for (int k = 0; k < 2; ++k) limits[k] = vec4(other[k]);\n}\n")
                  .empty());
  EXPECT_EQ(writeonly_reads(declared + "void main() {\n  limits[0] = limits[1] = vec4(0.0);\n}\n"),
            std::vector<std::string>{"line 4: limits is read"});
  EXPECT_EQ(writeonly_reads(declared + "void main() {\n  limits[0] += vec4(1.0);\n}\n").size(), 1u);
  EXPECT_EQ(writeonly_reads(declared + "void main() {\n  vec4 x = limits[0];\n}\n").size(), 1u);
  EXPECT_EQ(writeonly_reads(declared + "void main() {\n  if (limits[0] == vec4(0.0)) return;\n}\n").size(), 1u);
}

}  // namespace
