#include "server/bench/scale_benchmark.h"

#include <chrono>
#include <cstdio>
#include <memory>
#include <string>

#include "common/workload.h"
#include "server/bench/bench_runner.h"
#include "server/bench/cgal_baselines.h"
#include "server/core/dataset.h"
#include "server/core/locator_factory.h"
#include "server/core/triangulation.h"

namespace locator::bench {

namespace {

double NanosSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::nano>(
             std::chrono::steady_clock::now() - start)
      .count();
}

// Counts answers that disagree with the reference answers, and logs the
// first one.
class AnswerChecker {
 public:
  AnswerChecker(const Triangulation& t, std::string label)
      : t_(t), label_(std::move(label)) {}
  void Check(const Point2& q, const LocateResult& got,
             const LocateResult& reference) {
    if (t_.Agrees(q, got, reference)) return;
    if (mismatches_++ == 0) {
      std::fprintf(stderr,
                   "locator-bench: %s disagrees with CGAL at (%.17g, %.17g)\n",
                   label_.c_str(), q.x, q.y);
    }
  }
  size_t mismatches() const { return mismatches_; }

 private:
  const Triangulation& t_;
  std::string label_;
  size_t mismatches_ = 0;
};

}  // namespace

Status RunScale(const ScaleOptions& o, BenchReport* report) {
  size_t mismatches = 0;
  for (size_t n : o.sizes) {
    const Dataset dataset = GenerateUniform(n, 1);
    auto start = std::chrono::steady_clock::now();
    std::unique_ptr<Triangulation> t;
    Status s = Triangulation::Build(dataset, &t);
    if (!s.ok()) return s;
    report->Add(BenchRow{"build", "-", n, "triangulation", 0, 0, 0,
                         NanosSince(start), t->MemoryBytes()});
    CgalBaselines cgal(*t, dataset);
    report->Add(BenchRow{"build", "-", n, "cgal-hierarchy", 0, 0, 0,
                         cgal.hierarchy_build_seconds() * 1e9,
                         cgal.hierarchy_bytes()});

    for (WorkloadKind kind : AllWorkloadKinds()) {
      const std::string workload(WorkloadName(kind));
      const std::vector<Point2> all =
          WorkloadQueries(kind, t->bounding_box(), o.warmup + o.queries,
                          4242 + static_cast<int>(kind));
      const std::span<const Point2> warm = std::span(all).first(o.warmup);
      const std::span<const Point2> measured = std::span(all).subspan(o.warmup);
      std::vector<LocateResult> reference(measured.size());
      for (size_t i = 0; i < measured.size(); ++i) {
        reference[i] = cgal.LocateHierarchy(measured[i]);
      }
      LocateResult r;

      for (const std::string& strategy : StrategyNames()) {
        start = std::chrono::steady_clock::now();
        std::unique_ptr<PointLocator> locator;
        s = MakePointLocator(strategy, t->mesh(), o.tuning, &locator);
        if (!s.ok()) return s;
        const double build_ns = NanosSince(start);
        LocateAll(*locator, warm, nullptr);
        const std::span<const Point2> timed = measured.first(
            strategy == "walk" ? std::min(o.slow_queries, measured.size())
                               : measured.size());
        CostSums sums;
        AnswerChecker checker(*t, strategy + " on " + workload);
        for (size_t i = 0; i < timed.size(); ++i) {
          locator->Locate(timed[i], &r);
          sums.Add(r.cost);
          checker.Check(timed[i], r, reference[i]);
        }
        mismatches += checker.mismatches();
        const double ns = MedianNsPerQuery(
            timed, o.repeats, [&](const Point2& q) { locator->Locate(q, &r); });
        const size_t bytes = locator->Summary().memory_bytes;
        report->Add(BenchRow{"scale", workload, n, strategy, sums.mean_cost(),
                             sums.mean_faces(), sums.mean_comparisons(), ns,
                             bytes});
        if (kind == WorkloadKind::kUniform && strategy == "self-tuning") {
          report->Add(
              BenchRow{"build", "-", n, strategy, 0, 0, 0, build_ns, bytes});
        }
      }

      AnswerChecker checker(*t, "cgal-lasthint on " + workload);
      for (size_t i = 0; i < measured.size(); ++i) {
        checker.Check(measured[i], cgal.LocateLastHint(measured[i]),
                      reference[i]);
      }
      mismatches += checker.mismatches();
      const std::span<const Point2> slow =
          measured.first(std::min(o.slow_queries, measured.size()));
      report->Add(BenchRow{
          "scale", workload, n, "cgal-nohint", 0, 0, 0,
          MedianNsPerQuery(slow, o.repeats,
                           [&](const Point2& q) { r = cgal.LocateNoHint(q); }),
          0});
      report->Add(BenchRow{"scale", workload, n, "cgal-lasthint", 0, 0, 0,
                           MedianNsPerQuery(measured, o.repeats,
                                            [&](const Point2& q) {
                                              r = cgal.LocateLastHint(q);
                                            }),
                           0});
      report->Add(BenchRow{"scale", workload, n, "cgal-hierarchy", 0, 0, 0,
                           MedianNsPerQuery(measured, o.repeats,
                                            [&](const Point2& q) {
                                              r = cgal.LocateHierarchy(q);
                                            }),
                           cgal.hierarchy_bytes() > t->MemoryBytes()
                               ? cgal.hierarchy_bytes() - t->MemoryBytes()
                               : 0});
    }
  }
  if (mismatches > 0) {
    return Status::Internal(std::to_string(mismatches) +
                            " answers disagreed with CGAL");
  }
  return Status::OK();
}

}  // namespace locator::bench
