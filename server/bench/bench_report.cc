#include "server/bench/bench_report.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "server/bench/paper_figures.h"

namespace locator::bench {

namespace {

const std::vector<std::string> kLocatorStrategies = {
    "walk", "jump-and-walk", "adaptive-paper", "self-tuning"};
const std::vector<std::string> kCgalStrategies = {
    "cgal-nohint", "cgal-lasthint", "cgal-hierarchy"};

std::string Fixed(double v, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", digits, v);
  return buf;
}

// Distinct values of a row field, in first-seen order.
template <class Field>
std::vector<Field> Distinct(const std::vector<BenchRow>& rows,
                            const std::string& mode, Field BenchRow::*member) {
  std::vector<Field> out;
  for (const BenchRow& r : rows) {
    if (r.mode == mode &&
        std::find(out.begin(), out.end(), r.*member) == out.end()) {
      out.push_back(r.*member);
    }
  }
  return out;
}

}  // namespace

void BenchReport::PrintCsv(std::ostream& out) const {
  out << "mode,workload,n,strategy,mean_cost,mean_faces,mean_comparisons,"
         "ns_per_query,extra_bytes,retunes_per_1e6,tune_cpu_share,p50_ns,"
         "p999_ns,batch_ns_per_query,full_ns_per_query\n";
  for (const BenchRow& r : rows_) {
    out << r.mode << ',' << r.workload << ',' << r.n << ',' << r.strategy << ','
        << Fixed(r.mean_cost, 3) << ',' << Fixed(r.mean_faces, 3) << ','
        << Fixed(r.mean_comparisons, 3) << ',' << Fixed(r.ns_per_query, 1)
        << ',' << r.extra_bytes << ',' << Fixed(r.retunes_per_million, 1) << ','
        << Fixed(r.tune_cpu_share, 4) << ',' << Fixed(r.p50_ns, 0) << ','
        << Fixed(r.p999_ns, 0) << ',' << Fixed(r.batch_ns_per_query, 1) << ','
        << Fixed(r.full_ns_per_query, 1) << '\n';
  }
}

const BenchRow* BenchReport::Find(const std::string& mode,
                                  const std::string& workload, size_t n,
                                  const std::string& strategy) const {
  for (const BenchRow& r : rows_) {
    if (r.mode == mode && r.workload == workload && r.n == n &&
        r.strategy == strategy) {
      return &r;
    }
  }
  return nullptr;
}

void BenchReport::PrintMarkdown(std::ostream& out) const {
  PrintPaperTables(out);
  PrintDriftTable(out);
  PrintScaleTables(out);
}

void BenchReport::PrintPaperTables(std::ostream& out) const {
  // "paper", then the domain kinds' "paper-<kind>" in first-seen order.
  std::vector<std::string> modes;
  for (const BenchRow& r : rows_) {
    if (r.mode.starts_with("paper") &&
        std::find(modes.begin(), modes.end(), r.mode) == modes.end()) {
      modes.push_back(r.mode);
    }
  }
  for (const std::string& mode : modes) PrintPaperTables(mode, out);
}

void BenchReport::PrintPaperTables(const std::string& mode,
                                   std::ostream& out) const {
  const std::string kind =
      mode == "paper" ? "" : mode.substr(std::string("paper-").size()) + ": ";
  for (const std::string& workload :
       Distinct(rows_, mode, &BenchRow::workload)) {
    // The paper's own figures only beside its own setting.
    const PaperTable* paper =
        mode == "paper" ? FindPaperTable(workload) : nullptr;
    out << "\n### " << kind << workload << " (mean cost per query)\n\n| n |";
    if (paper) out << " paper J&W | paper Adaptive | paper gain |";
    for (const std::string& s : kLocatorStrategies) out << ' ' << s << " |";
    out << " adaptive-paper gain | self-tuning vs J&W |\n|---|";
    if (paper) out << "---|---|---|";
    for (size_t i = 0; i < kLocatorStrategies.size() + 2; ++i) out << "---|";
    out << '\n';
    for (size_t n : Distinct(rows_, mode, &BenchRow::n)) {
      out << "| " << n / 1000 << "K |";
      if (paper) {
        const auto it =
            std::find(kPaperSizes.begin(), kPaperSizes.end(), int(n));
        if (it != kPaperSizes.end()) {
          const size_t i = it - kPaperSizes.begin();
          out << ' ' << paper->jump_and_walk[i] << " | " << paper->adaptive[i]
              << " | "
              << Fixed(
                     100.0 * paper->jump_and_walk[i] / paper->adaptive[i] - 100,
                     0)
              << "% |";
        } else {
          out << " | | |";
        }
      }
      auto cost = [&](const std::string& s) {
        const BenchRow* r = Find(mode, workload, n, s);
        return r ? r->mean_cost : 0.0;
      };
      for (const std::string& s : kLocatorStrategies) {
        out << ' ' << Fixed(cost(s), 1) << " |";
      }
      const double jw = cost("jump-and-walk");
      out << ' ' << Fixed(100.0 * jw / cost("adaptive-paper") - 100, 0)
          << "% | " << Fixed(jw / cost("self-tuning"), 1) << "x |\n";
    }
  }
}

void BenchReport::PrintDriftTable(std::ostream& out) const {
  const auto windows = Distinct(rows_, "drift", &BenchRow::workload);
  if (windows.empty()) return;
  const size_t n = Distinct(rows_, "drift", &BenchRow::n).front();
  out << "\n### drift at n = " << n
      << " (mean cost per 500-query window; the square moves every 5000 "
         "queries)\n\n| window |";
  const std::vector<std::string> strategies = {"jump-and-walk",
                                               "adaptive-paper", "self-tuning"};
  for (const std::string& s : strategies) out << ' ' << s << " |";
  out << "\n|---|---|---|---|\n";
  for (const std::string& w : windows) {
    out << "| " << w.substr(w.find('@') + 1) << " |";
    for (const std::string& s : strategies) {
      const BenchRow* r = Find("drift", w, n, s);
      out << ' ' << (r ? Fixed(r->mean_cost, 1) : "") << " |";
    }
    out << '\n';
  }
}

void BenchReport::PrintScaleTables(std::ostream& out) const {
  std::vector<std::string> strategies = kLocatorStrategies;
  strategies.insert(strategies.end(), kCgalStrategies.begin(),
                    kCgalStrategies.end());
  for (size_t n : Distinct(rows_, "scale", &BenchRow::n)) {
    out << "\n### n = " << n
        << ": ns per locate (single thread, median of repeats) / mean cost\n\n"
        << "| workload |";
    for (const std::string& s : strategies) out << ' ' << s << " |";
    out << " hierarchy / self-tuning |\n|---|";
    for (size_t i = 0; i <= strategies.size(); ++i) out << "---|";
    out << '\n';
    for (const std::string& w : Distinct(rows_, "scale", &BenchRow::workload)) {
      out << "| " << w << " |";
      for (const std::string& s : strategies) {
        const BenchRow* r = Find("scale", w, n, s);
        out << ' '
            << (r ? Fixed(r->ns_per_query, 0) + " / " + Fixed(r->mean_cost, 1)
                  : "")
            << " |";
      }
      const BenchRow* h = Find("scale", w, n, "cgal-hierarchy");
      const BenchRow* st = Find("scale", w, n, "self-tuning");
      out << ' '
          << (h && st ? Fixed(h->ns_per_query / st->ns_per_query, 1) + "x" : "")
          << " |\n";
    }
    out << "\n| workload | strategy | batch ns/point | full answer ns | p50 ns "
           "| p99.9 ns | p99.9 / p50 | re-tunes per 10^6 | tuner CPU share |\n"
           "|---|---|---|---|---|---|---|---|---|\n";
    for (const BenchRow& r : rows_) {
      if (r.mode != "scale" || r.n != n || r.p50_ns <= 0) continue;
      out << "| " << r.workload << " | " << r.strategy << " | "
          << Fixed(r.batch_ns_per_query, 0) << " | "
          << Fixed(r.full_ns_per_query, 0) << " | " << Fixed(r.p50_ns, 0)
          << " | " << Fixed(r.p999_ns, 0) << " | "
          << Fixed(r.p999_ns / r.p50_ns, 1) << " | "
          << Fixed(r.retunes_per_million, 1) << " | "
          << Fixed(100 * r.tune_cpu_share, 2) << "% |\n";
    }
    out << "\n| structure | build ms | bytes | bytes per point | % of "
           "triangulation |\n|---|---|---|---|---|\n";
    const BenchRow* tri = Find("build", "-", n, "triangulation");
    for (const BenchRow& r : rows_) {
      if (r.mode != "build" || r.n != n) continue;
      out << "| " << r.strategy << " | " << Fixed(r.ns_per_query / 1e6, 1)
          << " | " << r.extra_bytes << " | "
          << Fixed(static_cast<double>(r.extra_bytes) / n, 1) << " | "
          << (tri && tri->extra_bytes
                  ? Fixed(100.0 * r.extra_bytes / tri->extra_bytes, 2) + "%"
                  : "")
          << " |\n";
    }
  }
}

}  // namespace locator::bench
