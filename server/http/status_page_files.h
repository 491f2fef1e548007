// The status page's static files (server/http/status_page/), embedded into
// the binary at build time by embed_files.cmake, so locatord serves them
// without any file at run time.
//
// Thread-safety: immutable data.

#ifndef LOCATOR_SERVER_HTTP_STATUS_PAGE_FILES_H_
#define LOCATOR_SERVER_HTTP_STATUS_PAGE_FILES_H_

#include <span>
#include <string_view>

namespace locator {

struct EmbeddedFile {
  std::string_view name;  // file name, e.g. "index.html"
  std::string_view bytes;
};

// Every file of the directory, sorted by name.
std::span<const EmbeddedFile> StatusPageFiles();

}  // namespace locator

#endif  // LOCATOR_SERVER_HTTP_STATUS_PAGE_FILES_H_
