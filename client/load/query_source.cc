#include "client/load/query_source.h"

#include <utility>

#include "client/points_reader.h"

namespace locator {
namespace {

constexpr std::string_view kReplayPrefix = "file:";

}  // namespace

bool QuerySource::IsReplay(std::string_view spec) {
  return spec.starts_with(kReplayPrefix);
}

Status QuerySource::Validate(std::string_view spec) {
  if (IsReplay(spec)) {
    return spec.size() > kReplayPrefix.size()
               ? Status::OK()
               : Status::InvalidArgument("workload file: needs a path");
  }
  WorkloadKind kind;
  return ParseWorkloadKind(spec, &kind);
}

Status QuerySource::Create(std::string_view spec, const BoundingBox& box,
                           uint64_t seed,
                           std::unique_ptr<QuerySource>* source) {
  if (IsReplay(spec)) {
    std::vector<Point2> points;
    Status status =
        ReadAllPoints(std::string(spec.substr(kReplayPrefix.size())), &points);
    if (!status.ok()) return status;
    source->reset(new QuerySource(std::move(points)));
    return Status::OK();
  }
  WorkloadKind kind;
  Status status = ParseWorkloadKind(spec, &kind);
  if (!status.ok()) return status;
  source->reset(new QuerySource(Workload(kind, box, seed)));
  return Status::OK();
}

QuerySource::QuerySource(Workload workload) : workload_(std::move(workload)) {}

QuerySource::QuerySource(std::vector<Point2> replay)
    : replay_(std::move(replay)) {}

Point2 QuerySource::NextLocked() {
  if (workload_) return workload_->Next();
  const Point2 point = replay_[replay_next_];
  replay_next_ = (replay_next_ + 1) % replay_.size();
  return point;
}

Point2 QuerySource::Next() {
  MutexLock lock(&mutex_);
  return NextLocked();
}

void QuerySource::Next(std::span<double> xs, std::span<double> ys) {
  MutexLock lock(&mutex_);
  for (size_t i = 0; i < xs.size(); ++i) {
    const Point2 point = NextLocked();
    xs[i] = point.x;
    ys[i] = point.y;
  }
}

}  // namespace locator
