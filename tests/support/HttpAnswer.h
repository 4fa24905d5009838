#pragma once
// One HTTP/1.1 answer read from the bytes a server wrote (serve's in-memory exchange), and
// held to the form RFC 9112 gives it: a status line, header fields whose names are tokens
// and whose values hold no control bytes, an empty line, and a body as long as its one
// Content-Length says. For the service's unit tests and the exchange's fuzz target.

#include <algorithm>
#include <cctype>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace figment::test {

inline bool sameFieldName(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

struct HttpAnswer {
  int status = 0;
  std::vector<std::pair<std::string, std::string>> headers;  // names as written
  std::string body;

  // How many fields are named `name` (any case).
  size_t count(std::string_view name) const {
    return size_t(std::count_if(headers.begin(), headers.end(),
                                [&](const auto& field) { return sameFieldName(field.first, name); }));
  }
  // The first field named `name`, or "".
  std::string header(std::string_view name) const {
    for (const auto& [key, value] : headers)
      if (sameFieldName(key, name)) return value;
    return "";
  }
};

namespace http_answer {

inline bool isToken(std::string_view text) {
  return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) ||
           std::string_view("!#$%&'*+-.^_`|~").find(c) != std::string_view::npos;
  });
}

// Visible ASCII, space and tab (RFC 9110 allows obs-text too, but no answer of ours has any).
inline bool isFieldText(std::string_view text) {
  return std::all_of(text.begin(), text.end(), [](char c) {
    const auto byte = static_cast<unsigned char>(c);
    return (byte >= 0x20 || byte == '\t') && byte < 0x7f;
  });
}

inline std::string readStatusLine(std::string_view line, HttpAnswer& answer) {
  const auto digit = [&](size_t i) { return i < line.size() && std::isdigit(static_cast<unsigned char>(line[i])); };
  if (line.substr(0, 9) != "HTTP/1.1 " || !digit(9) || !digit(10) || !digit(11) ||
      (line.size() > 12 && line[12] != ' ') || !isFieldText(line))
    return "a bad status line: " + std::string(line.substr(0, 80));
  answer.status = std::stoi(std::string(line.substr(9, 3)));
  return answer.status >= 100 && answer.status <= 599 ? "" : "a status out of range";
}

// The status line and header fields of one head, up to its empty line; "" or what is wrong.
inline std::string readHead(std::string_view& bytes, HttpAnswer& answer) {
  const size_t end = bytes.find("\r\n\r\n");
  if (end == std::string_view::npos) return "no empty line after the header fields";
  const std::string_view head = bytes.substr(0, end + 2);
  bytes.remove_prefix(end + 4);
  const size_t lineEnd = head.find("\r\n");
  if (std::string error = readStatusLine(head.substr(0, lineEnd), answer); !error.empty()) return error;
  answer.headers.clear();
  for (size_t at = lineEnd + 2; at < head.size();) {
    const size_t next = head.find("\r\n", at);
    const std::string_view field = head.substr(at, next - at);
    const size_t colon = field.find(':');
    if (colon == std::string_view::npos || !isToken(field.substr(0, colon)))
      return "a bad header field name: " + std::string(field.substr(0, 80));
    std::string_view value = field.substr(colon + 1);
    while (!value.empty() && (value.front() == ' ' || value.front() == '\t')) value.remove_prefix(1);
    while (!value.empty() && (value.back() == ' ' || value.back() == '\t')) value.remove_suffix(1);
    if (!isFieldText(value)) return "a control byte in the header field " + std::string(field.substr(0, colon));
    answer.headers.emplace_back(field.substr(0, colon), value);
    at = next + 2;
  }
  return "";
}

}  // namespace http_answer

// Reads one answer from `bytes` (interim 1xx answers before it passed over); "" when it is
// well formed, else what is wrong. A body shorter than its Content-Length is allowed only
// when empty: a HEAD's answer.
inline std::string readAnswer(std::string_view bytes, HttpAnswer& answer) {
  do {
    if (std::string error = http_answer::readHead(bytes, answer); !error.empty()) return error;
  } while (answer.status < 200);
  const std::string length = answer.header("Content-Length");
  if (answer.count("Content-Length") != 1 || length.empty() || length.size() > 9 ||
      length.find_first_not_of("0123456789") != std::string::npos)
    return "not one Content-Length that is a number";
  if (answer.count("Transfer-Encoding") != 0) return "a Transfer-Encoding beside a Content-Length";
  if (bytes.size() != std::stoul(length) && !bytes.empty())
    return "a body of " + std::to_string(bytes.size()) + " bytes, Content-Length " + length;
  answer.body = std::string(bytes);
  return "";
}

}  // namespace figment::test
