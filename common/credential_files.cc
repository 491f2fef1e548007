#include "common/credential_files.h"

#include <openssl/bio.h>
#include <openssl/err.h>
#include <openssl/evp.h>
#include <openssl/pem.h>
#include <openssl/x509.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>

namespace locator {
namespace {

Status FileError(std::string_view flag, std::string_view path,
                 std::string_view problem) {
  return Status::InvalidArgument("--" + std::string(flag) + " '" +
                                 std::string(path) +
                                 "': " + std::string(problem));
}

Status ReadSmallFile(std::string_view flag, const std::string& path,
                     std::string* contents) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    return FileError(flag, path,
                     std::string("cannot open: ") + std::strerror(errno));
  }
  // One byte more than allowed tells a file at the limit from a larger one.
  contents->resize(kMaxCredentialFileBytes + 1);
  in.read(contents->data(), static_cast<std::streamsize>(contents->size()));
  if (in.bad()) {
    return FileError(flag, path,
                     std::string("cannot read: ") + std::strerror(errno));
  }
  contents->resize(static_cast<size_t>(in.gcount()));
  if (contents->size() > kMaxCredentialFileBytes) {
    return FileError(flag, path, "larger than 1 MiB: not a credential file");
  }
  if (contents->empty()) return FileError(flag, path, "the file is empty");
  return Status::OK();
}

struct BioFree {
  void operator()(BIO* bio) const { BIO_free(bio); }
};
struct X509Free {
  void operator()(X509* cert) const { X509_free(cert); }
};
struct KeyFree {
  void operator()(EVP_PKEY* key) const { EVP_PKEY_free(key); }
};
using Bio = std::unique_ptr<BIO, BioFree>;
using Certificate = std::unique_ptr<X509, X509Free>;
using PrivateKey = std::unique_ptr<EVP_PKEY, KeyFree>;

Bio MemoryBio(const std::string& pem) {
  return Bio(BIO_new_mem_buf(pem.data(), static_cast<int>(pem.size())));
}

// Without a callback OpenSSL would prompt on the terminal for the passphrase
// of an encrypted key; a server has nobody to ask, so such a key fails.
int NoPassphrase(char* /*buf*/, int /*size*/, int /*rwflag*/, void* /*u*/) {
  return 0;
}

Certificate FirstCertificate(const std::string& pem) {
  return Certificate(
      PEM_read_bio_X509(MemoryBio(pem).get(), nullptr, NoPassphrase, nullptr));
}

PrivateKey ParsePrivateKey(const std::string& pem) {
  return PrivateKey(PEM_read_bio_PrivateKey(MemoryBio(pem).get(), nullptr,
                                            NoPassphrase, nullptr));
}

}  // namespace

Status ReadTokenFile(std::string_view flag, const std::string& path,
                     std::string* token) {
  std::string text;
  if (Status status = ReadSmallFile(flag, path, &text); !status.ok()) {
    return status;
  }
  if (text.ends_with('\n')) text.pop_back();
  if (text.ends_with('\r')) text.pop_back();
  if (text.empty()) return FileError(flag, path, "the token is empty");
  for (const char c : text) {
    if (c <= ' ' || c > '~') {
      return FileError(flag, path,
                       "the token must be one line of printable ASCII "
                       "without spaces");
    }
  }
  *token = std::move(text);
  return Status::OK();
}

Status ReadPemFile(std::string_view flag, const std::string& path, PemKind kind,
                   std::string* pem) {
  std::string text;
  if (Status status = ReadSmallFile(flag, path, &text); !status.ok()) {
    return status;
  }
  const bool parses = kind == PemKind::kCertificates
                          ? FirstCertificate(text) != nullptr
                          : ParsePrivateKey(text) != nullptr;
  // OpenSSL queues an error per failed parse; none of them is ours to keep.
  ERR_clear_error();
  if (!parses) {
    return FileError(flag, path,
                     kind == PemKind::kCertificates
                         ? "no PEM certificate could be read"
                         : "no unencrypted PEM private key could be read");
  }
  *pem = std::move(text);
  return Status::OK();
}

Status ReadKeyPairFiles(std::string_view flag_prefix,
                        const std::string& cert_path,
                        const std::string& key_path, KeyPairPem* pair) {
  const std::string cert_flag = std::string(flag_prefix) + "tls-cert";
  const std::string key_flag = std::string(flag_prefix) + "tls-key";
  if (cert_path.empty() != key_path.empty()) {
    return Status::InvalidArgument("--" + cert_flag + " and --" + key_flag +
                                   " go together: give both or neither");
  }
  if (cert_path.empty()) return Status::OK();
  Status status = ReadPemFile(cert_flag, cert_path, PemKind::kCertificates,
                              &pair->cert_chain);
  if (status.ok()) {
    status = ReadPemFile(key_flag, key_path, PemKind::kPrivateKey,
                         &pair->private_key);
  }
  if (!status.ok()) return status;
  const Certificate cert = FirstCertificate(pair->cert_chain);
  const PrivateKey key = ParsePrivateKey(pair->private_key);
  const bool matches = cert != nullptr && key != nullptr &&
                       X509_check_private_key(cert.get(), key.get()) == 1;
  ERR_clear_error();
  if (matches) return Status::OK();
  return Status::InvalidArgument("--" + key_flag + " '" + key_path +
                                 "' is not the private key of the first "
                                 "certificate in --" +
                                 cert_flag + " '" + cert_path + "'");
}

}  // namespace locator
