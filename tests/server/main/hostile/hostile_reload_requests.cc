// The admin request with the most to attack: Reload.

#include "tests/server/main/hostile/hostile_request_parts.h"
#include "tests/server/main/hostile/hostile_requests.h"

namespace locator::test {
namespace {

using Code = grpc::StatusCode;

// A hostile Reload spec and the refusals it may get.
struct ReloadSpec {
  std::string label;
  std::string text;
  std::vector<Code> refusals;
  std::vector<std::string> names;
  // A harmless option may be taken: the dataset reloads as it was.
  bool may_load = false;
};

constexpr size_t kHugeSpecBytes = size_t{1} << 20;

std::vector<ReloadSpec> ReloadSpecs(const HostileServer& server) {
  const std::vector<Code> denied = {Code::PERMISSION_DENIED};
  const std::vector<Code> refused = {Code::PERMISSION_DENIED,
                                     Code::INVALID_ARGUMENT};
  const std::vector<std::string> path_names = {"dataset", "reload dir", "file"};
  const std::vector<std::string> option_names = {"option", "oo",
                                                 "PRELUDE_STATEMENTS", "sql"};
  const std::string& gpkg = server.gpkg();
  const std::string out = server.outside_dir() + "/out.db";
  std::vector<ReloadSpec> specs;
  for (const std::string& path :
       {std::string("/dev/zero"), std::string("/dev/ptmx"),
        std::string("/etc/passwd"), std::string("/proc/self/environ"),
        server.secret(), server.reload_dir() + "/../outside/secret.db",
        std::string("ogr:/vsicurl/http://127.0.0.1:9/x.gpkg")}) {
    specs.push_back({path, path, denied, path_names});
  }
  specs.push_back({"the FIFO",
                   server.fifo(),
                   refused,
                   {"dataset", "fifo", "regular", "file"}});
  // No driver of the Reload allow-list identifies it.
  specs.push_back({"a garbage .gpkg",
                   server.reload_dir() + "/garbage.gpkg",
                   refused,
                   {"garbage.gpkg"}});
  specs.push_back({"oo ATTACH",
                   gpkg +
                       "?oo=PRELUDE_STATEMENTS=ATTACH "
                       "DATABASE '" +
                       server.secret() + "' AS x",
                   denied, option_names});
  specs.push_back({"oo VACUUM INTO",
                   gpkg + "?oo=PRELUDE_STATEMENTS=VACUUM INTO '" + out + "'",
                   denied, option_names});
  specs.push_back({"where with a sub-select",
                   gpkg + "?where=height > (SELECT -1e9)",
                   refused,
                   {"where", "option", "sql"},
                   true});
  specs.push_back({"oo LIST_ALL_TABLES", gpkg + "?oo=LIST_ALL_TABLES=YES",
                   refused, option_names, true});
  specs.push_back({"a_srs naming /dev/ptmx",
                   gpkg + "?a_srs=+proj=longlat +nadgrids=/dev/ptmx",
                   refused,
                   {"a_srs", "crs", "option"}});
  specs.push_back({"a layer nobody has",
                   gpkg + "?layer=nope",
                   {Code::INVALID_ARGUMENT, Code::NOT_FOUND},
                   {"layer", "nope"}});
  specs.push_back(
      {"1 MiB spec", std::string(kHugeSpecBytes, 'A'), refused, path_names});
  specs.push_back({"a generator past the point limit",
                   "uniform:99999999999:1",
                   {Code::RESOURCE_EXHAUSTED, Code::INVALID_ARGUMENT},
                   {"points", "uniform"}});
  for (const std::string& spec :
       {std::string("uniform:-1:1"), std::string("uniform:1e300:1"),
        std::string("uniform::")}) {
    specs.push_back({spec, spec, {Code::INVALID_ARGUMENT}, {"uniform"}});
  }
  return specs;
}

}  // namespace

std::vector<size_t> ReloadFieldCounts(const HostileServer& server) {
  std::vector<size_t> counts(kFieldCount, 0);
  counts[kFieldDataset] = HostileDatasetNames().size();
  counts[kFieldSpec] = ReloadSpecs(server).size();
  return counts;
}

HostileCase<v1::ReloadRequest> DrawReload(CaseDraw& draw,
                                          const HostileServer& server) {
  HostileCase<v1::ReloadRequest> c;
  const Target target =
      DrawTarget(draw, server, false, Transport::kGrpc, &c.expect);
  c.oracle = target.oracle;
  c.summary = target.summary;
  c.request.set_name(target.dataset);
  const std::vector<ReloadSpec> specs = ReloadSpecs(server);
  const std::optional<size_t> hostile = draw.Hostile(kFieldSpec, specs.size());
  if (hostile) {
    const ReloadSpec& spec = specs[*hostile];
    c.request.set_dataset(spec.text);
    c.summary += " spec " + spec.label;
    for (Code code : spec.refusals) {
      if (target.oracle == nullptr) break;
      spec.may_load ? c.expect.Allow(code, spec.names)
                    : c.expect.Require(code, spec.names);
    }
  }
  // Another reload of the same dataset may still be running.
  if (target.oracle != nullptr) {
    c.expect.Allow(Code::FAILED_PRECONDITION, {"in progress"});
  }
  return c;
}

}  // namespace locator::test
