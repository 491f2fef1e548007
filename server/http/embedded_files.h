// Static files embedded into locatord at build time by embed_files.cmake,
// so that it serves them without any file at run time: the status page
// (server/http/status_page/) and the web map (client/web/, with MapLibre).
//
// Thread-safety: immutable data.

#ifndef LOCATOR_SERVER_HTTP_EMBEDDED_FILES_H_
#define LOCATOR_SERVER_HTTP_EMBEDDED_FILES_H_

#include <span>
#include <string_view>

namespace locator {

struct EmbeddedFile {
  std::string_view name;  // file name, e.g. "index.html"
  std::string_view bytes;
};

// Every file of server/http/status_page/, sorted by name.
std::span<const EmbeddedFile> StatusPageFiles();

// Every file of client/web/, sorted by name.
std::span<const EmbeddedFile> WebExampleFiles();

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_EMBEDDED_FILES_H_
