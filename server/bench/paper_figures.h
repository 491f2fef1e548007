// The paper's published figures (Tables 1-4 of "Adaptive Point Location With
// Almost No Preprocessing in Delaunay Triangulations"): mean cost per query
// of Jump&Walk and of Adaptive Jump&Walk at n = 10K..50K, step 5K.

#ifndef LOCATOR_SERVER_BENCH_PAPER_FIGURES_H_
#define LOCATOR_SERVER_BENCH_PAPER_FIGURES_H_

#include <array>
#include <string_view>

namespace locator::bench {

struct PaperTable {
  std::string_view workload;
  std::array<int, 9> jump_and_walk;
  std::array<int, 9> adaptive;
};

inline constexpr std::array<int, 9> kPaperSizes = {
    10000, 15000, 20000, 25000, 30000, 35000, 40000, 45000, 50000};

inline constexpr std::array<PaperTable, 4> kPaperTables = {{
    {"1-cluster",
     {44, 51, 56, 58, 58, 57, 71, 75, 75},
     {14, 12, 12, 13, 13, 13, 18, 13, 21}},
    {"3-cluster",
     {41, 54, 55, 59, 63, 66, 66, 74, 74},
     {21, 23, 21, 25, 34, 26, 26, 34, 34}},
    {"d-cluster",
     {47, 54, 59, 63, 65, 70, 75, 74, 77},
     {29, 29, 34, 33, 43, 47, 55, 43, 44}},
    {"x-cluster",
     {46, 52, 58, 64, 66, 70, 73, 75, 83},
     {35, 38, 45, 49, 46, 57, 55, 54, 66}},
}};

// The paper's figures for `workload` at size index i, or nullptr.
inline const PaperTable* FindPaperTable(std::string_view workload) {
  for (const PaperTable& t : kPaperTables) {
    if (t.workload == workload) return &t;
  }
  return nullptr;
}

}  // namespace locator::bench

#endif  // LOCATOR_SERVER_BENCH_PAPER_FIGURES_H_
