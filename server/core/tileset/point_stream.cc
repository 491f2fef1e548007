#include "server/core/tileset/point_stream.h"

#include <algorithm>
#include <utility>

#include "server/core/dataset/generated_points.h"

namespace locator {
namespace {

class GeneratedStream : public PointStream {
 public:
  explicit GeneratedStream(const GeneratorSpec& spec)
      : spec_(spec), points_(spec) {}

  bool has_values() const override { return false; }
  Status Rewind() override {
    points_ = GeneratedPoints(spec_);
    drawn_ = 0;
    return Status::OK();
  }
  Status Read(size_t max_points, std::vector<Point2>* points,
              std::vector<double>* values) override {
    const size_t count = std::min(max_points, spec_.n - drawn_);
    points->resize(count);
    for (Point2& p : *points) p = points_.Next();
    values->clear();
    drawn_ += count;
    return Status::OK();
  }

 private:
  const GeneratorSpec spec_;
  GeneratedPoints points_;
  size_t drawn_ = 0;
};

class HeldStream : public PointStream {
 public:
  explicit HeldStream(Dataset dataset) : dataset_(std::move(dataset)) {}

  bool has_values() const override { return dataset_.has_values(); }
  Status Rewind() override {
    next_ = 0;
    return Status::OK();
  }
  Status Read(size_t max_points, std::vector<Point2>* points,
              std::vector<double>* values) override {
    const size_t count = std::min(max_points, dataset_.points.size() - next_);
    const auto from = static_cast<std::ptrdiff_t>(next_);
    const auto to = static_cast<std::ptrdiff_t>(next_ + count);
    points->assign(dataset_.points.begin() + from,
                   dataset_.points.begin() + to);
    values->clear();
    if (has_values()) {
      values->assign(dataset_.values.begin() + from,
                     dataset_.values.begin() + to);
    }
    next_ += count;
    return Status::OK();
  }

 private:
  const Dataset dataset_;
  size_t next_ = 0;
};

}  // namespace

std::unique_ptr<PointStream> GeneratedPointStream(const GeneratorSpec& spec) {
  return std::make_unique<GeneratedStream>(spec);
}

std::unique_ptr<PointStream> DatasetPointStream(Dataset dataset) {
  return std::make_unique<HeldStream>(std::move(dataset));
}

}  // namespace locator
