#include <string>
#include <utility>
#include <vector>

#include "tests/server/main/hostile/hostile_http_rows.h"

namespace locator::test {

std::vector<HttpRow> TileRows() {
  const HttpHeaders json = {{"Content-Type", "application/json"}};
  const std::vector<unsigned> bad = {400};
  std::vector<HttpRow> rows;
  const std::string tiles = "/v1/datasets/utm/tiles/";
  const std::vector<std::pair<std::string, std::string>> bad_tiles = {
      {"a tile at zoom 2^64", tiles + "18446744073709551616/0/0.png"},
      {"a tile x of 5000 digits",
       tiles + "3/" + std::string(5000, '7') + "/0.png"},
      {"a tile y of -1", tiles + "3/0/-1.png"},
      {"a tile zoom of NaN", tiles + "nan/0/0.png"},
      {"a 6 KiB encoding",
       tiles + "0/0/0.png?encoding=" + std::string(6000, 'e')},
      {"a tile of a dataset without a CRS",
       "/v1/datasets/plain/tiles/0/0/0.png"},
      {"a hillshade azimuth of 1e300",
       "/v1/datasets/utm/hillshade/0/0/0.png?azimuth=1e300"},
      {"a hillshade altitude of NaN",
       "/v1/datasets/utm/hillshade/0/0/0.png?altitude=nan"},
      {"a hillshade z factor of a denormal's negative",
       "/v1/datasets/utm/hillshade/0/0/0.png?z_factor=-4.9e-324"},
      {"a hillshade scale of inf",
       "/v1/datasets/utm/hillshade/0/0/0.png?scale=inf"},
      {"a 6 KiB hillshade scale",
       "/v1/datasets/utm/hillshade/0/0/0.png?scale=" + std::string(6000, '9')},
      {"a hillshade tile at zoom 2^64",
       "/v1/datasets/utm/hillshade/18446744073709551616/0/0.png"},
  };
  for (const auto& [label, target] : bad_tiles) {
    rows.push_back({label, "GET", target, "", {}, "", bad});
  }
  const std::vector<HttpRow> tile_rows = {
      {"a tile", "GET", tiles + "0/0/0.png", "", {}, "", {200}, IsPng},
      {"a hillshade tile of denormal scale and huge exaggeration",
       "GET",
       "/v1/datasets/utm/hillshade/0/0/0.png?scale=4.9e-324&z_factor=1e9",
       "",
       {},
       "",
       {200},
       IsPng},
      {"a tile of a NUL dataset",
       "GET",
       "/v1/datasets/%00/tiles/0/0/0.png",
       "",
       {},
       "",
       {404}},
      {"a tile path too deep",
       "GET",
       tiles + "1/1/1/1/1/1/1.png",
       "",
       {},
       "",
       {404}},
      {"a 6 KiB If-None-Match",
       "GET",
       tiles + "0/0/0.png",
       "",
       {{"If-None-Match", std::string(6000, ',')}},
       "",
       {200},
       IsPng},
      {"POST a tile", "POST", tiles + "0/0/0.png", "{}", json, "", {405}},
      {"TileJSON",
       "GET",
       "/v1/datasets/utm/tiles.json",
       "",
       {},
       "",
       {200},
       IsJson},
      {"TileJSON for a Host that is none",
       "GET",
       "/v1/datasets/utm/tiles.json",
       "",
       {{"Host", "evil\"}, {\"x\":\"<script>"}},
       "",
       {200, 400},
       IsJson},
  };
  rows.insert(rows.end(), tile_rows.begin(), tile_rows.end());

  // Cesium terrain: the same hostile z/x/y, levels past the data's (empty
  // tiles, not errors), and hostile Accept and Accept-Encoding.
  const std::string mesh = "/v1/datasets/utm/quantized-mesh/";
  for (const auto& [label, target] :
       std::vector<std::pair<std::string, std::string>>{
           {"a terrain tile at level 2^64",
            mesh + "18446744073709551616/0/0.terrain"},
           {"a terrain tile x of 5000 digits",
            mesh + "3/" + std::string(5000, '7') + "/0.terrain"},
           {"a terrain tile y of -1", mesh + "3/0/-1.terrain"},
           {"a terrain tile x past the level's 2^(z+1)",
            mesh + "3/16/0.terrain"},
           {"a terrain tile level of NaN", mesh + "nan/0/0.terrain"},
           {"a terrain tile of a dataset without a CRS",
            "/v1/datasets/plain/quantized-mesh/0/0/0.terrain"},
       }) {
    rows.push_back({label, "GET", target, "", {}, "", bad});
  }
  const std::vector<HttpRow> mesh_rows = {
      {"layer.json", "GET", mesh + "layer.json", "", {}, "", {200}, IsJson},
      {"a terrain tile at level 0",
       "GET",
       mesh + "0/1/0.terrain",
       "",
       {},
       "",
       {200},
       IsQuantizedMesh},
      {"the deepest terrain tile, far from the data",
       "GET",
       mesh + "24/33554431/16777215.terrain",
       "",
       {},
       "",
       {200},
       IsQuantizedMesh},
      {"the deepest terrain tile at the data",
       "GET",
       mesh + "24/18175317/13016227.terrain",
       "",
       {},
       "",
       {200},
       IsQuantizedMesh},
      {"a 6 KiB Accept of commas",
       "GET",
       mesh + "0/1/0.terrain",
       "",
       {{"Accept", std::string(6000, ',')}},
       "",
       {406}},
      {"a 6 KiB Accept-Encoding with q=NaN",
       "GET",
       mesh + "0/1/0.terrain",
       "",
       {{"Accept-Encoding", "gzip;q=nan," + std::string(6000, ';')}},
       "",
       {200}},
      {"POST a terrain tile",
       "POST",
       mesh + "0/0/0.terrain",
       "{}",
       json,
       "",
       {405}},
  };
  rows.insert(rows.end(), mesh_rows.begin(), mesh_rows.end());
  return rows;
}

}  // namespace locator::test
