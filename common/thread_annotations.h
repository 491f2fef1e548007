// Clang thread-safety annotations, as macros.
//
// With clang and -Wthread-safety the compiler checks, at every call site,
// that a member marked GUARDED_BY(mu) is touched only with mu held and that a
// method marked REQUIRES(mu) is called only with mu held. On compilers
// without the attribute (gcc) every macro expands to nothing, so annotated
// code builds the same everywhere. See
// https://clang.llvm.org/docs/ThreadSafetyAnalysis.html for the semantics.
//
// Thread-safety: compile-time only; nothing here exists at run time.

#ifndef LOCATOR_COMMON_THREAD_ANNOTATIONS_H_
#define LOCATOR_COMMON_THREAD_ANNOTATIONS_H_

#if defined(__clang__) && defined(__has_attribute)
#if __has_attribute(guarded_by)
#define LOCATOR_THREAD_ANNOTATION(x) __attribute__((x))
#endif
#endif
#ifndef LOCATOR_THREAD_ANNOTATION
#define LOCATOR_THREAD_ANNOTATION(x)  // no-op without clang's analysis
#endif

// gRPC's headers bring abseil's legacy thread_annotations.h, which defines
// GUARDED_BY, PT_GUARDED_BY, ACQUIRED_BEFORE, ACQUIRED_AFTER and
// NO_THREAD_SAFETY_ANALYSIS with the same attributes; these definitions
// replace them, whichever comes first.
#undef GUARDED_BY
#undef PT_GUARDED_BY
#undef ACQUIRED_BEFORE
#undef ACQUIRED_AFTER
#undef NO_THREAD_SAFETY_ANALYSIS

// A class that is a lock (a "capability"), named `x` in diagnostics.
#define CAPABILITY(x) LOCATOR_THREAD_ANNOTATION(capability(x))
// An RAII class that holds a capability for its lifetime.
#define SCOPED_CAPABILITY LOCATOR_THREAD_ANNOTATION(scoped_lockable)

// The member is read and written only with `x` held.
#define GUARDED_BY(x) LOCATOR_THREAD_ANNOTATION(guarded_by(x))
// The data the (smart) pointer member points to is guarded by `x`.
#define PT_GUARDED_BY(x) LOCATOR_THREAD_ANNOTATION(pt_guarded_by(x))

// Lock ordering: this capability is taken before / after the listed ones.
#define ACQUIRED_BEFORE(...) \
  LOCATOR_THREAD_ANNOTATION(acquired_before(__VA_ARGS__))
#define ACQUIRED_AFTER(...) \
  LOCATOR_THREAD_ANNOTATION(acquired_after(__VA_ARGS__))

// The caller must hold the capabilities (exclusively / shared).
#define REQUIRES(...) \
  LOCATOR_THREAD_ANNOTATION(requires_capability(__VA_ARGS__))
#define REQUIRES_SHARED(...) \
  LOCATOR_THREAD_ANNOTATION(requires_shared_capability(__VA_ARGS__))

// The function acquires / releases the capabilities (exclusively / shared).
#define ACQUIRE(...) LOCATOR_THREAD_ANNOTATION(acquire_capability(__VA_ARGS__))
#define ACQUIRE_SHARED(...) \
  LOCATOR_THREAD_ANNOTATION(acquire_shared_capability(__VA_ARGS__))
#define RELEASE(...) LOCATOR_THREAD_ANNOTATION(release_capability(__VA_ARGS__))
#define RELEASE_SHARED(...) \
  LOCATOR_THREAD_ANNOTATION(release_shared_capability(__VA_ARGS__))
#define RELEASE_GENERIC(...) \
  LOCATOR_THREAD_ANNOTATION(release_generic_capability(__VA_ARGS__))

// The function tries to acquire; the first argument is the return value that
// means success.
#define TRY_ACQUIRE(...) \
  LOCATOR_THREAD_ANNOTATION(try_acquire_capability(__VA_ARGS__))
#define TRY_ACQUIRE_SHARED(...) \
  LOCATOR_THREAD_ANNOTATION(try_acquire_shared_capability(__VA_ARGS__))

// The caller must not hold the capabilities (the function takes them).
#define EXCLUDES(...) LOCATOR_THREAD_ANNOTATION(locks_excluded(__VA_ARGS__))

// Asserts at run time that the capability is held; the analysis trusts it.
#define ASSERT_CAPABILITY(x) LOCATOR_THREAD_ANNOTATION(assert_capability(x))
#define ASSERT_SHARED_CAPABILITY(x) \
  LOCATOR_THREAD_ANNOTATION(assert_shared_capability(x))

// The function returns a reference to the capability `x`.
#define RETURN_CAPABILITY(x) LOCATOR_THREAD_ANNOTATION(lock_returned(x))

// Turns the analysis off for one function; say why at each use.
#define NO_THREAD_SAFETY_ANALYSIS \
  LOCATOR_THREAD_ANNOTATION(no_thread_safety_analysis)

#endif  // LOCATOR_COMMON_THREAD_ANNOTATIONS_H_
