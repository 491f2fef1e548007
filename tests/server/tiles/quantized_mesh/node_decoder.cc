#include "tests/server/tiles/quantized_mesh/node_decoder.h"

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <sstream>

namespace locator::test {
namespace {

// The folder of package.json, decode_tiles.js and node_modules (set by
// CMake).
constexpr char kDecoderDir[] = LOCATOR_QUANTIZED_MESH_DECODER_DIR;

std::string Quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) {
    if (c == '\'') {
      out += "'\\''";
    } else {
      out += c;
    }
  }
  return out + "'";
}

}  // namespace

Status DecodeWithNode(const std::vector<std::string>& files,
                      std::vector<DecodedTile>* tiles) {
  tiles->clear();
  const std::filesystem::path dir(kDecoderDir);
  if (!std::filesystem::exists(dir / "node_modules" / "@here" /
                               "quantized-mesh-decoder" / "package.json")) {
    return Status::FailedPrecondition(
        "@here/quantized-mesh-decoder is not installed in " + dir.string() +
        "/node_modules: run deploy/install-deps.sh (npm ci there)");
  }
  std::string command = "node " + Quoted((dir / "decode_tiles.js").string());
  for (const std::string& file : files) command += " " + Quoted(file);
  command += " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return Status::Internal("popen failed: " + command);
  std::string output;
  char buffer[1 << 16];
  size_t got;
  while ((got = fread(buffer, 1, sizeof buffer, pipe)) > 0) {
    output.append(buffer, got);
  }
  const int status = pclose(pipe);
  if (!WIFEXITED(status) || WEXITSTATUS(status) == 127) {
    return Status::FailedPrecondition(
        "node is not installed (Debian's nodejs and npm: run "
        "deploy/install-deps.sh): " +
        output.substr(0, 400));
  }
  if (WEXITSTATUS(status) != 0) {
    return Status::Internal("the decoder failed: " + output.substr(0, 2000));
  }
  std::istringstream in(output);
  std::string word;
  while (in >> word) {
    if (word != "tile") return Status::Internal("unexpected '" + word + "'");
    DecodedTile t;
    std::string file;
    in >> file >> word;
    for (double& c : t.centre) in >> c;
    in >> t.min_height >> t.max_height;
    for (double& c : t.sphere_centre) in >> c;
    in >> t.sphere_radius;
    for (double& c : t.occlusion) in >> c;
    size_t n = 0;
    in >> word >> n;
    t.vertices.resize(n);
    for (auto& v : t.vertices) in >> v[0] >> v[1] >> v[2];
    in >> word >> n;
    t.triangles.resize(n);
    for (auto& v : t.triangles) in >> v[0] >> v[1] >> v[2];
    for (std::vector<uint32_t>& edge : t.edges) {
      in >> word >> n;
      edge.resize(n);
      for (uint32_t& i : edge) in >> i;
    }
    if (!in) return Status::Internal("could not read the decoder's output");
    tiles->push_back(std::move(t));
  }
  if (tiles->size() != files.size()) {
    return Status::Internal("the decoder read " +
                            std::to_string(tiles->size()) + " of " +
                            std::to_string(files.size()) + " tiles");
  }
  return Status::OK();
}

}  // namespace locator::test
