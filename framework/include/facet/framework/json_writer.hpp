#pragma once
// A minimal streaming JSON writer for reports (run statistics, comparisons). Keys and strings are
// escaped; numbers that are not finite are written as null, since JSON has no NaN.

#include <ostream>
#include <string_view>
#include <vector>

namespace facet {

class JsonWriter {
 public:
  explicit JsonWriter(std::ostream& out, int indent = 2) : out_(out), indent_(indent) {}

  JsonWriter& begin_object();
  JsonWriter& end_object();
  JsonWriter& begin_array();
  JsonWriter& end_array();
  JsonWriter& key(std::string_view name);
  JsonWriter& value(std::string_view text);
  JsonWriter& value(const char* text) { return value(std::string_view(text)); }
  JsonWriter& value(double number);
  JsonWriter& value(std::int64_t number);
  JsonWriter& value(bool flag);
  JsonWriter& null();

 private:
  void before_value();
  void newline();
  void write_string(std::string_view text);

  std::ostream& out_;
  int indent_;
  struct Level {
    bool is_object;
    bool empty = true;
  };
  std::vector<Level> levels_;
  bool after_key_ = false;
};

}  // namespace facet
