// GrpcLifetime: keeps the gRPC library initialised for the length of a
// program's main(), and on destruction shuts it down and waits until gRPC's
// own threads have exited (grpc_shutdown_blocking). Without it, returning
// from main() runs the process's exit-time cleanup (OpenSSL's atexit handler
// among it) while gRPC threads may still be finishing TLS work, a race that
// ASAN caught as a double free in locator-load.
//
// OpenSSL is told not to clean up at exit (OPENSSL_INIT_NO_ATEXIT) before
// gRPC first initialises it: a gRPC executor thread may still be finishing
// TLS work when the process exits (seen under ASAN as a double free of an
// OpenSSL thread's error state, in thread T7, after grpc_shutdown_blocking
// returned), and the process's memory goes back to the system at exit
// anyway.
//
// Declare one first thing in main(), so that every gRPC object the program
// makes is destroyed before it. Thread-safety: one per process, on the main
// thread.

#ifndef LOCATOR_COMMON_GRPC_LIFETIME_H_
#define LOCATOR_COMMON_GRPC_LIFETIME_H_

#include <grpc/grpc.h>
#include <openssl/crypto.h>

namespace locator {

class GrpcLifetime {
 public:
  GrpcLifetime() {
    OPENSSL_init_crypto(OPENSSL_INIT_NO_ATEXIT, nullptr);
    grpc_init();
  }
  ~GrpcLifetime() { grpc_shutdown_blocking(); }

  GrpcLifetime(const GrpcLifetime&) = delete;
  GrpcLifetime& operator=(const GrpcLifetime&) = delete;
};

}  // namespace locator

#endif  // LOCATOR_COMMON_GRPC_LIFETIME_H_
