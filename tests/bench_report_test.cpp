// The benchmark tables as people read them (bench/suites/report.hpp, issue 20): numbers to 4
// significant digits in columns a terminal holds, the CSV with the cells as they were.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "bench/suites/report.hpp"

namespace clothlab::bench {
namespace {

TEST(BenchReport, PeopleReadFourSignificantDigits) {
  EXPECT_EQ(for_people(num(1.0 / 60.0)), "0.01667");
  EXPECT_EQ(for_people(num(0.000481557484)), "0.0004816");
  EXPECT_EQ(for_people(num(9.24272598e-05)), "9.243e-05");
  EXPECT_EQ(for_people(num(123456.789)), "1.235e+05");
  // Already short, integers and text stay as they are.
  EXPECT_EQ(for_people("1.000"), "1.000");
  EXPECT_EQ(for_people("0.06"), "0.06");
  EXPECT_EQ(for_people("4166"), "4166");
  EXPECT_EQ(for_people("1234567"), "1234567");
  EXPECT_EQ(for_people("symplectic_euler"), "symplectic_euler");
  EXPECT_EQ(for_people("12.3 %"), "12.3 %");
  EXPECT_EQ(for_people("nan"), "nan");
}

// The contact suite's slowest second: the largest mean of a window of consecutive frames, found
// wherever it lies (first, last, middle), and the whole run's mean when it is shorter.
TEST(BenchReport, SlowestWindowIsTheLargestMeanOfConsecutiveValues) {
  EXPECT_DOUBLE_EQ(slowest_window_mean({5, 1, 1, 1}, 2), 3.0);
  EXPECT_DOUBLE_EQ(slowest_window_mean({1, 1, 1, 4, 6}, 2), 5.0);
  EXPECT_DOUBLE_EQ(slowest_window_mean({1, 9, 1, 1, 8, 2}, 3), 11.0 / 3.0);
  // One slow value alone is not the slowest window of three.
  EXPECT_DOUBLE_EQ(slowest_window_mean({1, 1, 9, 1, 1, 4, 4, 4}, 3), 4.0);
  EXPECT_DOUBLE_EQ(slowest_window_mean({2, 4}, 60), 3.0);
  EXPECT_DOUBLE_EQ(slowest_window_mean({}, 60), 0.0);
}

// The printed table shows the short form and the note; the CSV keeps %.9g.
TEST(BenchReport, PrintedShortCsvFull) {
  Table t;
  t.title = "T";
  t.note = quick_note(true, "the big grids");
  t.columns = {"dt (s)", "method"};
  t.add({num(1.0 / 60.0), "bdf2"});
  std::ostringstream out;
  print_table(out, t);
  EXPECT_NE(out.str().find("\nT\n--quick leaves out: the big grids\n"), std::string::npos)
      << out.str();
  EXPECT_NE(out.str().find("0.01667  bdf2"), std::string::npos) << out.str();
  EXPECT_EQ(out.str().find("0.0166666667"), std::string::npos) << out.str();
  EXPECT_EQ(quick_note(false, "anything"), "");

  const std::string path =
      (std::filesystem::temp_directory_path() / "clothlab_bench_report_test.csv").string();
  write_csv(path, t);
  std::ifstream f(path);
  std::stringstream csv;
  csv << f.rdbuf();
  std::filesystem::remove(path);
  EXPECT_EQ(csv.str(), "dt (s),method\n0.0166666667,bdf2\n");
}

}  // namespace
}  // namespace clothlab::bench
