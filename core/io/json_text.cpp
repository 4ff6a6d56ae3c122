#include "core/io/json_text.h"

#include <cmath>
#include <cstring>
#include <memory>
#include <unordered_set>
#include <vector>

#include "core/support/quoted_text.h"
#include "core/support/error.h"

namespace gps {

namespace {

using Json = nlohmann::json;

// Deeper nesting than kMaxJsonDepth is refused as it is read: none of gpsurf's documents nests more
// than a few levels, and a DOM of a million empty arrays would take a hundred times the file's size.
struct TooDeep {};
// A key given twice in one object (nlohmann keeps the last, silently).
struct RepeatedKey {};
// A number whose digits are not zero but that a double holds only as 0 (1e-400).
struct Underflow {};

// nlohmann's DOM builder that also knows where in the document it is, so that an error names the
// element it met (its own message names only the byte). With a sink, a top-level array's elements are
// built one at a time and handed over as each ends, so that the whole document is never held.
class LocatingParser {
public:
  using Dom = nlohmann::detail::json_sax_dom_parser<Json>;
  LocatingParser(Json& result, const JsonElementSink* sink) : result_(result), sink_(sink) {
    if (!sink_) dom_ = std::make_unique<Dom>(result_, true);
  }

  bool null() { return value() && dom_->null() && ended_value(); }
  bool boolean(bool v) { return value() && dom_->boolean(v) && ended_value(); }
  bool number_integer(Json::number_integer_t v) { return value() && dom_->number_integer(v) && ended_value(); }
  bool number_unsigned(Json::number_unsigned_t v) { return value() && dom_->number_unsigned(v) && ended_value(); }
  bool number_float(Json::number_float_t v, const std::string& s) {
    if (v == 0 && s.find_first_of("123456789") < s.find_first_of("eE")) throw Underflow{};
    return value() && dom_->number_float(v, s) && ended_value();
  }
  bool string(std::string& v) { return value() && dom_->string(v) && ended_value(); }
  bool binary(Json::binary_t& v) { return value() && dom_->binary(v) && ended_value(); }
  bool start_object(size_t n) {
    if (!value()) return false;
    if (levels_.size() >= kMaxJsonDepth) throw TooDeep{};
    levels_.push_back({false, 0, {}, {}});
    return dom_->start_object(n);
  }
  bool key(std::string& k) {
    levels_.back().key = k;
    if (!levels_.back().keys.insert(k).second) throw RepeatedKey{};
    return dom_->key(k);
  }
  bool end_object() {
    levels_.pop_back();
    return dom_->end_object() && ended_value();
  }
  bool start_array(size_t n) {
    if (sink_ && levels_.empty()) {  // the streamed array itself: its elements get a DOM each
      levels_.push_back({true, 0, {}, {}});
      streaming_ = true;
      return true;
    }
    if (!value()) return false;
    if (levels_.size() >= kMaxJsonDepth) throw TooDeep{};
    levels_.push_back({true, 0, {}, {}});
    return dom_->start_array(n);
  }
  bool end_array() {
    levels_.pop_back();
    if (streaming_ && levels_.empty()) return true;
    return dom_->end_array() && ended_value();
  }
  template <class Exception>
  bool parse_error(std::size_t, const std::string&, const Exception& e) {
    throw e;
  }

  /// The top-level value was an array whose elements went to the sink.
  bool streamed() const { return streaming_; }
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
    std::unordered_set<std::string> keys;  // every key so far, for an object
  };
  // A value begins: counted in its array; a streamed array's element gets a DOM of its own. False
  // (parsing stops) where a sink was given and the top-level value is not an array.
  bool value() {
    if (!levels_.empty() && levels_.back().array) ++levels_.back().started;
    if (!sink_) return true;
    if (!streaming_) return false;
    if (levels_.size() == 1) {
      element_ = Json();
      dom_ = std::make_unique<Dom>(element_, true);
    }
    return true;
  }
  // A value ended: at the top of a streamed array, its element goes to the sink.
  bool ended_value() {
    if (streaming_ && levels_.size() == 1) {
      (*sink_)(levels_.back().started - 1, std::move(element_));
      element_ = Json();
    }
    return true;
  }

  Json& result_;
  const JsonElementSink* sink_;
  std::unique_ptr<Dom> dom_;
  Json element_;
  bool streaming_ = false;
  std::vector<Level> levels_;
};

// Runs `parser` over `text`, turning nlohmann's errors into usage errors in our words.
void run_parser(const std::string& text, const std::string& source, const std::string& top_name,
                LocatingParser& parser) {
  const std::string prefix = source.empty() ? "" : source + ": ";
  // Where the parser stopped, as "ops[3].cuts: " (nothing at the top).
  const auto at = [&] {
    std::string path = top_name + parser.where();
    if (!path.empty() && path[0] == '.') path.erase(0, 1);
    return path.empty() ? path : path + ": ";
  };
  if (const void* nul = std::memchr(text.data(), 0, text.size()))
    throw usage_error(prefix + "not valid JSON (a NUL byte at byte " +
                      std::to_string(static_cast<const char*>(nul) - text.data() + 1) + ")");
  try {
    Json::sax_parse(text, &parser);
  } catch (const Json::parse_error& e) {
    throw usage_error(prefix + "not valid JSON (byte " + std::to_string(e.byte) + ")");
  } catch (const Json::out_of_range& e) {
    throw usage_error(prefix + at() + "a number beyond the range of a double");
  } catch (const RepeatedKey&) {
    throw usage_error(prefix + at() + "the key is given twice in its object");
  } catch (const Underflow&) {
    throw usage_error(prefix + at() + "a number too small for a double (it would be read as 0)");
  } catch (const TooDeep&) {
    throw usage_error(prefix + at() + "nested more than " + std::to_string(kMaxJsonDepth) + " levels deep");
  } catch (const Json::exception& e) {
    throw usage_error(prefix + "not valid JSON");
  }
}

}  // namespace

Json parse_json(const std::string& text, const std::string& source, const std::string& top_name) {
  Json result;
  LocatingParser parser(result, nullptr);
  run_parser(text, source, top_name, parser);
  return result;
}

bool parse_json_array(const std::string& text, const std::string& source, const std::string& top_name,
                      const JsonElementSink& sink) {
  Json unused;
  LocatingParser parser(unused, &sink);
  run_parser(text, source, top_name, parser);
  if (parser.streamed()) return true;
  parse_json(text, source, top_name);  // not an array: its syntax errors as parse_json reports them
  return false;
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
