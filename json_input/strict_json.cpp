#include "json_input/strict_json.h"

#include <unordered_set>
#include <vector>

namespace strata::json_input {
namespace {

using nlohmann::json;

// Follows the parser's events to know, at each open container, its keys so far and which
// element is open, so that a repeated key can be named by its full path.
class Rules {
 public:
  explicit Rules(std::string source) : source_(std::move(source)) {}

  bool operator()(int depth, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        // `depth` counts the containers already open around this one.
        if (depth + 1 > kMaxDepth)
          throw JsonInputError(source_ + ": nested deeper than " + std::to_string(kMaxDepth) +
                               " levels (the limit for a JSON input)");
        next_element();
        open_.push_back(Level{event == json::parse_event_t::object_start, {}, {}, 0});
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        open_.pop_back();
        break;
      case json::parse_event_t::key: {
        Level& top = open_.back();
        top.current = parsed.get<std::string>();
        if (!top.keys.insert(top.current).second)
          throw JsonInputError(source_ + ": duplicate key '" + path() + "' (each key may appear once)");
        break;
      }
      case json::parse_event_t::value:
        next_element();
        break;
    }
    return true;  // keep everything: the document is built as usual
  }

 private:
  struct Level {
    bool object;
    std::unordered_set<std::string> keys;
    std::string current;  // the key being read (objects)
    size_t elements;      // elements started so far (arrays)
  };

  void next_element() {
    if (!open_.empty() && !open_.back().object) ++open_.back().elements;
  }

  // "memory.l2.banks", "lights[2].position": the path to the key being read.
  std::string path() const {
    std::string p;
    for (const Level& l : open_) {
      if (!l.object) {
        p += "[" + std::to_string(l.elements - 1) + "]";
      } else {
        p += (p.empty() ? "" : ".") + l.current;
      }
    }
    return p;
  }

  std::string source_;
  std::vector<Level> open_;
};

// nlohmann's "[json.exception.parse_error.101] parse error at line 2, column 5: syntax error ..."
// becomes "<source>: not valid JSON at line 2, column 5: syntax error ...".
JsonSyntaxError syntax_error(const std::string& source, const json::exception& e) {
  std::string what = e.what();
  const std::string marker = "parse error ";
  const size_t at = what.find(marker);
  if (at != std::string::npos) {
    what = " " + what.substr(at + marker.size());
  } else {
    const size_t close = what.find("] ");  // out_of_range.406: a number beyond a double
    what = ": " + (close == std::string::npos ? what : what.substr(close + 2));
  }
  return JsonSyntaxError(source + ": not valid JSON" + what);
}

template <typename Input>
json parse_with_rules(Input&& input, const std::string& source) {
  try {
    return json::parse(std::forward<Input>(input), Rules(source), /*allow_exceptions=*/true);
  } catch (const json::exception& e) {
    throw syntax_error(source, e);
  }
}

}  // namespace

json parse_strict(std::istream& in, const std::string& source) { return parse_with_rules(in, source); }

json parse_strict(const std::string& text, const std::string& source) { return parse_with_rules(text, source); }

}  // namespace strata::json_input
