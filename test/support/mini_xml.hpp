#pragma once
// A small strict XML reader for tests of the SVG that facet writes: elements, attributes in
// double quotes, text, the five predefined entities and an optional <?xml ...?> declaration.
// Anything else (an unclosed or mismatched tag, a stray '<' or '&', an unquoted attribute) makes
// it fail, so that a test can tell well-formed output from almost-well-formed output.

#include <cctype>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace facet::test {

struct XmlElement {
  std::string name;
  std::map<std::string, std::string> attributes;
  std::vector<XmlElement> children;
  std::string text;  // the text directly inside, entities decoded

  // Every element named `element_name` below this one, depth first.
  void find_all(const std::string& element_name, std::vector<const XmlElement*>& out) const {
    for (const auto& child : children) {
      if (child.name == element_name) out.push_back(&child);
      child.find_all(element_name, out);
    }
  }
  std::vector<const XmlElement*> all(const std::string& element_name) const {
    std::vector<const XmlElement*> out;
    find_all(element_name, out);
    return out;
  }
  std::string attribute(const std::string& key) const {
    const auto it = attributes.find(key);
    return it == attributes.end() ? std::string() : it->second;
  }
};

class MiniXmlParser {
 public:
  explicit MiniXmlParser(std::string_view text) : text_(text) {}

  // The root element, or nullopt with error() saying where the text is not well-formed.
  std::optional<XmlElement> parse() {
    skip_space();
    if (text_.substr(at_).starts_with("<?xml")) {
      const auto end = text_.find("?>", at_);
      if (end == std::string_view::npos) return fail("unterminated XML declaration");
      at_ = end + 2;
    }
    skip_space();
    auto root = element();
    if (!root) return std::nullopt;
    skip_space();
    if (at_ != text_.size()) return fail("text after the root element");
    return root;
  }
  const std::string& error() const { return error_; }

 private:
  std::nullopt_t fail(const std::string& why) {
    if (error_.empty()) error_ = why + " at offset " + std::to_string(at_);
    return std::nullopt;
  }
  void skip_space() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_])))
      ++at_;
  }
  std::string name() {
    const std::size_t from = at_;
    while (at_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[at_])) ||
                                  text_[at_] == '-' || text_[at_] == '_' || text_[at_] == ':'))
      ++at_;
    return std::string(text_.substr(from, at_ - from));
  }
  // Decodes entities in text or an attribute value up to `stop`; a raw '<' is an error.
  std::optional<std::string> characters(char stop) {
    std::string out;
    while (at_ < text_.size() && text_[at_] != stop) {
      const char c = text_[at_];
      if (c == '<') return fail("'<' in text or attribute");
      if (c == '&') {
        const auto end = text_.find(';', at_);
        if (end == std::string_view::npos) return fail("unterminated entity");
        const std::string_view entity = text_.substr(at_ + 1, end - at_ - 1);
        static const std::map<std::string_view, char> kEntities = {
            {"amp", '&'}, {"lt", '<'}, {"gt", '>'}, {"quot", '"'}, {"apos", '\''}};
        const auto it = kEntities.find(entity);
        if (it == kEntities.end()) return fail("unknown entity &" + std::string(entity) + ";");
        out += it->second;
        at_ = end + 1;
        continue;
      }
      out += c;
      ++at_;
    }
    return out;
  }
  std::optional<XmlElement> element() {
    if (at_ >= text_.size() || text_[at_] != '<') return fail("expected '<'");
    ++at_;
    XmlElement element;
    element.name = name();
    if (element.name.empty()) return fail("element without a name");
    while (true) {
      skip_space();
      if (at_ >= text_.size()) return fail("unterminated tag <" + element.name);
      if (text_.substr(at_).starts_with("/>")) {
        at_ += 2;
        return element;
      }
      if (text_[at_] == '>') {
        ++at_;
        break;
      }
      const std::string key = name();
      if (key.empty()) return fail("bad attribute in <" + element.name);
      if (at_ >= text_.size() || text_[at_] != '=') return fail("attribute without '='");
      ++at_;
      if (at_ >= text_.size() || text_[at_] != '"') return fail("unquoted attribute " + key);
      ++at_;
      auto value = characters('"');
      if (!value || at_ >= text_.size()) return fail("unterminated attribute " + key);
      ++at_;
      if (!element.attributes.emplace(key, *value).second)
        return fail("duplicate attribute " + key);
    }
    while (true) {
      auto text = characters('<');
      if (!text) return std::nullopt;
      element.text += *text;
      if (at_ >= text_.size()) return fail("unclosed <" + element.name + ">");
      if (text_.substr(at_).starts_with("</")) {
        at_ += 2;
        if (name() != element.name) return fail("mismatched </...> for <" + element.name + ">");
        skip_space();
        if (at_ >= text_.size() || text_[at_] != '>') return fail("bad closing tag");
        ++at_;
        return element;
      }
      auto child = this->element();
      if (!child) return std::nullopt;
      element.children.push_back(std::move(*child));
    }
  }

  std::string_view text_;
  std::size_t at_ = 0;
  std::string error_;
};

// The number of "x,y" pairs in a polyline's points attribute.
inline std::size_t polyline_points(const XmlElement& polyline) {
  std::size_t count = 0;
  bool in_pair = false;
  for (const char c : polyline.attribute("points")) {
    const bool space = std::isspace(static_cast<unsigned char>(c)) != 0;
    if (!space && !in_pair) ++count;
    in_pair = !space;
  }
  return count;
}

}  // namespace facet::test
