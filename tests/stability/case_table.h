// Each checked case of the stability suite is also a row of its table (table_main.cpp): the
// check records the test property "case: NAME" = "EXPECTED<TAB>GOT<TAB>ok|FAIL".
#pragma once
#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace pineda::test {

inline void record_case(const std::string& name, const std::string& expected, const std::string& got, bool ok) {
  ::testing::Test::RecordProperty("case: " + name, expected + "\t" + got + "\t" + (ok ? "ok" : "FAIL"));
}

template <typename T>
std::string case_text(const T& v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

// got == expected.
template <typename T, typename U>
void expect_case(const std::string& name, const T& expected, const U& got) {
  const bool ok = expected == got;
  EXPECT_TRUE(ok) << name << ": expected " << expected << ", got " << got;
  record_case(name, case_text(expected), case_text(got), ok);
}

// got <= bound (a maximum error).
template <typename T, typename U>
void expect_case_at_most(const std::string& name, const T& bound, const U& got) {
  const bool ok = got <= bound;
  EXPECT_TRUE(ok) << name << ": expected at most " << bound << ", got " << got;
  record_case(name, "<= " + case_text(bound), case_text(got), ok);
}

}  // namespace pineda::test
