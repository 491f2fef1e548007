#include "server/bench/bench_report.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace locator::bench {
namespace {

void AddStrategies(const std::string& mode, const std::string& workload,
                   double walk_cost, BenchReport* report) {
  double cost = walk_cost;
  for (const char* s :
       {"walk", "jump-and-walk", "adaptive-paper", "self-tuning"}) {
    report->Add(BenchRow{mode, workload, 10000, s, cost, cost, 0, 0, 0});
    cost /= 2;
  }
}

std::string Markdown(const BenchReport& report) {
  std::ostringstream out;
  report.PrintMarkdown(out);
  return out.str();
}

TEST(BenchReport, DomainKindsGetTablesOfTheirOwnWithoutThePapersFigures) {
  BenchReport report;
  AddStrategies("paper", "1-cluster", 100, &report);
  AddStrategies("paper-aniso", "1-cluster", 400, &report);
  const std::string md = Markdown(report);
  const size_t delaunay = md.find("### 1-cluster (mean cost per query)");
  const size_t aniso = md.find("### aniso: 1-cluster (mean cost per query)");
  ASSERT_NE(delaunay, std::string::npos) << md;
  ASSERT_NE(aniso, std::string::npos) << md;
  ASSERT_LT(delaunay, aniso);
  // The paper's published figures sit beside its own setting only.
  const std::string delaunay_table = md.substr(delaunay, aniso - delaunay);
  const std::string aniso_table = md.substr(aniso);
  EXPECT_NE(delaunay_table.find("paper J&W"), std::string::npos);
  EXPECT_EQ(aniso_table.find("paper J&W"), std::string::npos);
  // Each table shows its own rows: walk 400, jump-and-walk 200, ...
  EXPECT_NE(aniso_table.find("| 10K | 400.0 | 200.0 | 100.0 | 50.0 |"),
            std::string::npos)
      << aniso_table;
  EXPECT_NE(delaunay_table.find("| 100.0 | 50.0 | 25.0 | 12.5 |"),
            std::string::npos)
      << delaunay_table;
}

TEST(BenchReport, CsvKeepsTheDomainModeInTheModeColumn) {
  BenchReport report;
  AddStrategies("paper-cdt", "uniform", 8, &report);
  std::ostringstream out;
  report.PrintCsv(out);
  EXPECT_NE(out.str().find("\npaper-cdt,uniform,10000,self-tuning,1.000,"),
            std::string::npos)
      << out.str();
}

}  // namespace
}  // namespace locator::bench
