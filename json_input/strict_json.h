// Reading a JSON document that a user wrote (a chip config, a scene description, a --set value).
// nlohmann's parser alone accepts a key given twice (the last silently wins), nests without
// limit, and places a syntax error only inside its exception text. Its parse is iterative, but
// the walks after it are not (dump(), the config binder's recursion): a file nested 100,000
// levels deep overflowed the stack (issue 39 F6). Here each of those is an error naming the
// source, found while parsing, so a deep file is refused at its 65th level without reading on.
#pragma once

#include <istream>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

namespace strata::json_input {

// Far deeper than any of our formats needs (a chip config nests 4 levels, a scene description
// 3), and shallow enough that every recursive walk of a document stays well within the stack.
constexpr int kMaxDepth = 64;

// Every refusal: "<source>: <what is wrong>".
class JsonInputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};
// Not JSON at all ("<source>: not valid JSON at line L, column C: ..."), as opposed to JSON
// that breaks the rules above; a --set value that is not JSON is taken as a bare word.
class JsonSyntaxError : public JsonInputError {
 public:
  using JsonInputError::JsonInputError;
};

// One document from `in` (or `text`); `source` names it in the errors. Refuses nesting deeper
// than kMaxDepth and a key repeated in one object (named by its path, e.g. 'memory.l2.banks').
nlohmann::json parse_strict(std::istream& in, const std::string& source);
nlohmann::json parse_strict(const std::string& text, const std::string& source);

}  // namespace strata::json_input
