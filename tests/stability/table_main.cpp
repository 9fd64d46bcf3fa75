// The stability suite's main: runs the tests, then prints every recorded case as a table
// (case, expected, got). `--table FILE` also writes it there as Markdown.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace {

struct CaseRow {
  std::string test, name, expected, got, verdict;
};

std::vector<std::string> split_tabs(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string part;
  while (std::getline(in, part, '\t')) out.push_back(part);
  return out;
}

class CaseTableListener : public ::testing::EmptyTestEventListener {
 public:
  explicit CaseTableListener(std::vector<CaseRow>& rows) : rows_(rows) {}
  void OnTestEnd(const ::testing::TestInfo& info) override {
    const ::testing::TestResult& r = *info.result();
    const std::string test = std::string(info.test_suite_name()) + "." + info.name();
    for (int i = 0; i < r.test_property_count(); ++i) {
      const ::testing::TestProperty& p = r.GetTestProperty(i);
      const std::string key = p.key();
      if (key.rfind("case: ", 0) != 0) continue;
      const std::vector<std::string> v = split_tabs(p.value());
      if (v.size() != 3) continue;
      rows_.push_back({test, key.substr(6), v[0], v[1], v[2]});
    }
  }

 private:
  std::vector<CaseRow>& rows_;
};

void print_markdown(std::ostream& out, const std::vector<CaseRow>& rows) {
  out << "| test | case | expected | got | |\n| --- | --- | --- | --- | --- |\n";
  for (const CaseRow& r : rows)
    out << "| " << r.test << " | " << r.name << " | " << r.expected << " | " << r.got << " | " << r.verdict << " |\n";
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  std::string table_path;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--table") == 0 && i + 1 < argc) table_path = argv[++i];
    else if (std::strncmp(argv[i], "--table=", 8) == 0) table_path = argv[i] + 8;
  }
  std::vector<CaseRow> rows;
  ::testing::UnitTest::GetInstance()->listeners().Append(new CaseTableListener(rows));
  const int status = RUN_ALL_TESTS();
  if (!rows.empty()) {
    std::cout << "\nStability cases (" << rows.size() << "):\n";
    print_markdown(std::cout, rows);
  }
  if (!table_path.empty()) {
    std::ofstream f(table_path);
    print_markdown(f, rows);
    if (!f) {
      std::fprintf(stderr, "cannot write %s\n", table_path.c_str());
      return status ? status : 1;
    }
  }
  return status;
}
