#include "core/io/json_text.h"

#include <cmath>
#include <cstring>
#include <vector>

#include "core/support/quoted_text.h"
#include "core/support/error.h"

namespace gps {

namespace {

using Json = nlohmann::json;

// nlohmann's DOM builder that also knows where in the document it is, so that an error names the
// element it met (its own message names only the byte).
class LocatingParser : public nlohmann::detail::json_sax_dom_parser<Json> {
public:
  explicit LocatingParser(Json& result) : json_sax_dom_parser(result, true) {}

  bool null() { return started() && json_sax_dom_parser::null(); }
  bool boolean(bool v) { return started() && json_sax_dom_parser::boolean(v); }
  bool number_integer(Json::number_integer_t v) { return started() && json_sax_dom_parser::number_integer(v); }
  bool number_unsigned(Json::number_unsigned_t v) { return started() && json_sax_dom_parser::number_unsigned(v); }
  bool number_float(Json::number_float_t v, const std::string& s) {
    return started() && json_sax_dom_parser::number_float(v, s);
  }
  bool string(std::string& v) { return started() && json_sax_dom_parser::string(v); }
  bool binary(Json::binary_t& v) { return started() && json_sax_dom_parser::binary(v); }
  bool start_object(size_t n) {
    started();
    levels_.push_back({false, 0, {}});
    return json_sax_dom_parser::start_object(n);
  }
  bool key(std::string& k) {
    levels_.back().key = k;
    return json_sax_dom_parser::key(k);
  }
  bool end_object() {
    levels_.pop_back();
    return json_sax_dom_parser::end_object();
  }
  bool start_array(size_t n) {
    started();
    levels_.push_back({true, 0, {}});
    return json_sax_dom_parser::start_array(n);
  }
  bool end_array() {
    levels_.pop_back();
    return json_sax_dom_parser::end_array();
  }

  /// The element being read, as "[3].cuts" (the innermost level names the element not yet started).
  std::string where() const {
    std::string out;
    for (size_t i = 0; i < levels_.size(); ++i) {
      const Level& l = levels_[i];
      if (l.array)
        out += "[" + std::to_string(i + 1 == levels_.size() ? l.started : l.started - 1) + "]";
      else
        out += "." + escaped(l.key.substr(0, kMaxQuotedCharacters));
    }
    return out;
  }

private:
  struct Level {
    bool array;
    size_t started;   // elements begun, for an array
    std::string key;  // the last key, for an object
  };
  bool started() {
    if (!levels_.empty() && levels_.back().array) ++levels_.back().started;
    return true;
  }
  std::vector<Level> levels_;
};

}  // namespace

Json parse_json(const std::string& text, const std::string& source, const std::string& top_name) {
  const std::string prefix = source.empty() ? "" : source + ": ";
  if (const void* nul = std::memchr(text.data(), 0, text.size()))
    throw usage_error(prefix + "not valid JSON (a NUL byte at byte " +
                      std::to_string(static_cast<const char*>(nul) - text.data() + 1) + ")");
  Json result;
  LocatingParser parser(result);
  try {
    Json::sax_parse(text, &parser);
  } catch (const Json::parse_error& e) {
    throw usage_error(prefix + "not valid JSON (byte " + std::to_string(e.byte) + ")");
  } catch (const Json::out_of_range& e) {
    std::string path = top_name + parser.where();
    if (!path.empty() && path[0] == '.') path.erase(0, 1);
    throw usage_error(prefix + (path.empty() ? "" : path + ": ") + "a number beyond the range of a double");
  } catch (const Json::exception& e) {
    throw usage_error(prefix + "not valid JSON");
  }
  return result;
}

std::string json_shown(const Json& value) {
  if (value.is_number()) return value.dump();
  const std::string kind = value.type_name();
  return (kind == "array" || kind == "object" ? "an " : "a ") + kind;
}

long long json_integer(const Json& value, long long lo, long long hi) {
  if (value.is_number_unsigned()) {
    if (hi >= 0 && value.get<unsigned long long>() <= static_cast<unsigned long long>(hi) &&
        static_cast<long long>(value.get<unsigned long long>()) >= lo)
      return static_cast<long long>(value.get<unsigned long long>());
  } else if (value.is_number_integer()) {
    if (value.get<long long>() >= lo && value.get<long long>() <= hi) return value.get<long long>();
  }
  throw usage_error("must be an integer from " + std::to_string(lo) + " to " + std::to_string(hi) + ", got " +
                    json_shown(value));
}

double json_number(const Json& value) {
  if (!value.is_number() || !std::isfinite(value.get<double>()))
    throw usage_error("must be a finite number, got " + json_shown(value));
  return value.get<double>();
}

std::string json_error_words(const nlohmann::json::exception& e) {
  std::string words = e.what();
  if (const size_t tag_end = words.find("] "); words.rfind("[json.exception.", 0) == 0 && tag_end != std::string::npos)
    words.erase(0, tag_end + 2);
  return escaped(words.substr(0, 160));
}

}  // namespace gps
