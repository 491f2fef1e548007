// The hostile HTTP table's rows for the elevation APIs: Open Topo Data
// (/opentopodata/v1/{dataset}) and OGC API - EDR (/edr/), with extreme
// doubles, sizes past the batch and sample limits, hostile WKT, CRSs,
// polylines, bodies and dataset names, on the hostile server's datasets
// "utm" (UTM zone 33N) and "plain" (no CRS). Open Topo Data's errors have
// its own shape, checked here instead of as ApiErrors.

#include <string>
#include <utility>
#include <vector>

#include "tests/server/http/json_value.h"
#include "tests/server/main/hostile/hostile_http_rows.h"
#include "tests/server/main/hostile/hostile_server.h"

namespace locator::test {
namespace {

// The most bytes of an error message a row accepts.
constexpr size_t kMaxErrorBytes = 1024;

// An Open Topo Data answer: "OK" with results, or an error of its shape
// with a short message.
std::string IsOpenTopoDataAnswer(const HttpReply& reply) {
  JsonValue json;
  if (Header(reply, "content-type") != "application/json" ||
      !ParseJson(reply.body, &json).ok()) {
    return "not JSON: " + reply.body.substr(0, 200);
  }
  try {
    const std::string& status = json["status"].string();
    if (reply.status == 200) {
      return status == "OK" && !json["results"].array().empty()
                 ? ""
                 : "a 200 that is not OK with results";
    }
    const std::string& error = json["error"].string();
    if (status != "INVALID_REQUEST" && status != "REQUEST_DENIED" &&
        status != "SERVER_ERROR") {
      return "status '" + status + "'";
    }
    if (error.empty() || error.size() > kMaxErrorBytes) {
      return "an error message of " + std::to_string(error.size()) + " bytes";
    }
  } catch (const std::exception& e) {
    return std::string("not Open Topo Data's shape: ") + e.what();
  }
  return "";
}

std::string IsCoverage(const HttpReply& reply) {
  JsonValue json;
  return Header(reply, "content-type") == "application/prs.coverage+json" &&
                 ParseJson(reply.body, &json).ok()
             ? ""
             : "not CoverageJSON: " + Header(reply, "content-type");
}

// "lat,lng|..." of `n` points around the hostile hill.
std::string LatLngs(size_t n) {
  std::string text;
  for (size_t i = 0; i < n; ++i) {
    text += (i == 0 ? "" : "|") + std::string("49.6") + std::to_string(i % 10) +
            ",15.0" + std::to_string(i % 7);
  }
  return text;
}

}  // namespace

std::vector<HttpRow> ElevationRows() {
  const HttpHeaders json = {{"Content-Type", "application/json"}};
  const std::string odt = "/opentopodata/v1/utm?locations=";
  std::vector<HttpRow> rows;
  // Open Topo Data: every reply has its shape, 200 or 400 as listed.
  const std::vector<std::tuple<std::string, std::string, unsigned>> gets = {
      {"Open Topo Data at a point", odt + "49.65,15", 200},
      {"Open Topo Data at 4.9e-324,-0", odt + "4.9e-324,-0", 200},
      {"Open Topo Data at NaN", odt + "nan,15", 400},
      {"Open Topo Data at inf", odt + "49,-inf", 400},
      {"Open Topo Data at 1e300", odt + "1e300,1e300", 400},
      {"Open Topo Data at 1e400", odt + "1e400,15", 400},
      {"Open Topo Data at a hex float", odt + "0x1p3,15", 400},
      {"Open Topo Data with 6 KiB of commas", odt + std::string(6000, ','),
       400},
      {"Open Topo Data with 6 KiB of bars", odt + std::string(6000, '|'), 400},
      {"Open Topo Data with a 6 KiB polyline", odt + std::string(6000, '~'),
       400},
      {"Open Topo Data with a polyline past 90 degrees",
       odt + "enc:_c%60%7Cy@?", 400},
      {"Open Topo Data with a bad escape", odt + "%zz", 400},
      {"Open Topo Data with a NUL", odt + "49,15%00", 400},
      {"Open Topo Data with samples past 32 bits",
       odt + "49.6,15|49.7,15&samples=4294967297", 400},
      {"Open Topo Data with samples past the limit",
       odt + "49.6,15|49.7,15&samples=" +
           std::to_string(HostileLimits::kProfileSamples + 1),
       400},
      {"Open Topo Data with a path of one point", odt + "49.6,15&samples=5",
       400},
      {"Open Topo Data with a path across the world",
       odt + "-89,-179|89,179&samples=5", 400},
      {"Open Topo Data with cubic interpolation",
       odt + "49.65,15&interpolation=cubic", 400},
      {"Open Topo Data with a 6 KiB interpolation",
       odt + "49.65,15&interpolation=" + std::string(6000, 'x'), 400},
      {"Open Topo Data with nodata_value 1e999",
       odt + "49.65,15&nodata_value=1e999", 400},
      {"Open Topo Data on a dataset without a CRS",
       "/opentopodata/v1/plain?locations=49.65,15", 400},
      {"Open Topo Data on a NUL dataset", "/opentopodata/v1/%00?locations=1,1",
       400},
      {"Open Topo Data on a 6 KiB dataset",
       "/opentopodata/v1/" + std::string(6000, 'd') + "?locations=1,1", 400},
      {"Open Topo Data on nine datasets",
       "/opentopodata/v1/utm,b,c,d,e,f,g,h,i?locations=1,1", 400},
      {"Open Topo Data on a dataset twice",
       "/opentopodata/v1/utm,utm?locations=49.65,15", 400},
      {"Open Topo Data on 6000 commas",
       "/opentopodata/v1/" + std::string(6000, ',') + "?locations=1,1", 400},
      {"Open Topo Data on a dataset and one without a CRS",
       "/opentopodata/v1/utm,plain?locations=49.65,15", 400},
      {"Open Topo Data without a dataset", "/opentopodata/v1/", 404},
      {"Open Topo Data too deep", "/opentopodata/v1/utm/1/2", 404},
  };
  for (const auto& [label, target, status] : gets) {
    rows.push_back({label,
                    "GET",
                    target,
                    "",
                    {},
                    "",
                    {status},
                    IsOpenTopoDataAnswer,
                    /*api_error=*/false});
  }
  const std::string post = "/opentopodata/v1/utm";
  const std::vector<std::tuple<std::string, std::string, HttpHeaders, unsigned>>
      posts = {
          {"Open Topo Data JSON POST", R"({"locations":"49.65,15"})", json,
           200},
          {"Open Topo Data POST past the batch limit",
           R"({"locations":")" + LatLngs(HostileLimits::kBatchPoints + 1) +
               R"("})",
           json, 400},
          {"Open Topo Data POST of an array", "[1,2]", json, 400},
          {"Open Topo Data POST nested 10^5 deep",
           "{\"locations\":" + std::string(100000, '[') +
               std::string(100000, ']') + "}",
           json, 400},
          {"Open Topo Data POST of a number as locations",
           R"({"locations": 1e400})", json, 400},
          {"Open Topo Data POST as text/plain",
           "locations=49.65,15",
           {{"Content-Type", "text/plain"}},
           400},
          {"Open Topo Data form POST",
           "locations=49.65,15%7C49.66,15",
           {{"Content-Type", "application/x-www-form-urlencoded"}},
           200},
      };
  for (const auto& [label, body, headers, status] : posts) {
    rows.push_back({label,
                    "POST",
                    post,
                    body,
                    headers,
                    "",
                    {status},
                    IsOpenTopoDataAnswer,
                    /*api_error=*/false});
  }
  rows.push_back({"Open Topo Data DELETE",
                  "DELETE",
                  post,
                  "",
                  {},
                  "",
                  {405},
                  IsOpenTopoDataAnswer,
                  /*api_error=*/false});

  // OGC API - EDR: errors are ApiErrors.
  const std::string position = "/edr/collections/utm/position?coords=";
  const std::string trajectory = "/edr/collections/utm/trajectory?coords=";
  std::string many_points = "MULTIPOINT(";
  for (int i = 0; i < 400; ++i) {
    many_points += (i == 0 ? "" : ",") + std::string("15.0") +
                   std::to_string(i % 10) + "%2049.6" + std::to_string(i % 7);
  }
  many_points += ")";
  const std::vector<std::tuple<std::string, std::string, unsigned>> edr = {
      {"EDR position", position + "POINT(15%2049.65)", 200},
      {"EDR position of 400 points", position + many_points, 200},
      {"EDR position at NaN", position + "POINT(NaN%2049)", 400},
      {"EDR position at inf", position + "POINT(15%20-inf)", 400},
      {"EDR position at 1e300 in CRS84", position + "POINT(1e300%201e300)",
       400},
      {"EDR position at 1e300 in UTM",
       position + "POINT(1e300%201e300)&crs=EPSG:32633", 200},
      {"EDR position at denormals in UTM",
       position + "POINT(4.9e-324%20-4.9e-324)&crs=EPSG:32633", 200},
      {"EDR position of 6 KiB of parentheses",
       position + std::string(6000, '('), 400},
      {"EDR position of 6 KiB of digits",
       position + "POINT(" + std::string(6000, '9') + "%201)", 400},
      {"EDR position of a collection",
       position + "GEOMETRYCOLLECTION(POINT(1%201))", 400},
      {"EDR position with a 6 KiB crs",
       position + "POINT(15%2049)&crs=" + std::string(6000, 'c'), 400},
      {"EDR position with a PROJ string crs",
       position + "POINT(15%2049)&crs=%2Bproj%3Dlonglat", 400},
      {"EDR position with a 6 KiB f",
       position + "POINT(15%2049)&f=" + std::string(6000, 'f'), 400},
      {"EDR position in CRS84 on a dataset without a CRS",
       "/edr/collections/plain/position?coords=POINT(1%201)&crs=CRS84", 400},
      {"EDR trajectory", trajectory + "LINESTRING(15%2049.6,15.01%2049.7)",
       200},
      {"EDR trajectory across the world",
       trajectory + "LINESTRING(-179%20-89,179%2089)", 400},
      {"EDR trajectory at 1e300 in UTM",
       trajectory + "LINESTRING(-1e300%20-1e300,1e300%201e300)&crs=EPSG:32633",
       200},
      {"EDR trajectory with samples past 32 bits",
       trajectory + "LINESTRING(15%2049.6,15.01%2049.7)&samples=4294967296",
       400},
      {"EDR trajectory with samples past the limit",
       trajectory + "LINESTRING(15%2049.6,15.01%2049.7)&samples=" +
           std::to_string(HostileLimits::kProfileSamples + 1),
       429},
      {"EDR collection of a NUL dataset", "/edr/collections/%00", 404},
      {"EDR collection of a 6 KiB dataset",
       "/edr/collections/" + std::string(6000, 'd'), 404},
      {"EDR query nobody serves", "/edr/collections/utm/cube", 404},
  };
  for (const auto& [label, target, status] : edr) {
    rows.push_back({label,
                    "GET",
                    target,
                    "",
                    {},
                    "",
                    {status},
                    status == 200 ? IsCoverage : nullptr});
  }
  const std::vector<HttpRow> edr_rows = {
      {"EDR landing page", "GET", "/edr/", "", {}, "", {200}, IsJson},
      {"EDR conformance", "GET", "/edr/conformance", "", {}, "", {200}, IsJson},
      {"EDR collections", "GET", "/edr/collections", "", {}, "", {200}, IsJson},
      {"POST to EDR", "POST", "/edr/collections", "{}", json, "", {405}},
  };
  rows.insert(rows.end(), edr_rows.begin(), edr_rows.end());
  return rows;
}

}  // namespace locator::test
