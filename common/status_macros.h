// RETURN_IF_ERROR and ASSIGN_OR_RETURN: early return of a failed Status.
//
// Inside a function returning Status or StatusOr<U>:
//   RETURN_IF_ERROR(Check(x));              // returns Check's Status if not OK
//   ASSIGN_OR_RETURN(Mesh mesh, Load(path)); // declares and moves the value,
//                                            // or returns Load's Status
// Each argument is evaluated once. Internal to the project: installed
// headers do not define macros.

#ifndef LOCATOR_COMMON_STATUS_MACROS_H_
#define LOCATOR_COMMON_STATUS_MACROS_H_

#include <utility>

#include "locator/status.h"
#include "locator/status_or.h"

#define LOCATOR_STATUS_CONCAT_INNER_(a, b) a##b
#define LOCATOR_STATUS_CONCAT_(a, b) LOCATOR_STATUS_CONCAT_INNER_(a, b)

#define RETURN_IF_ERROR(expr)                                                \
  do {                                                                       \
    if (::locator::Status locator_status_ = (expr); !locator_status_.ok()) { \
      return locator_status_;                                                \
    }                                                                        \
  } while (false)

#define LOCATOR_ASSIGN_OR_RETURN_IMPL_(holder, lhs, expr) \
  auto holder = (expr);                                   \
  if (!holder.ok()) return std::move(holder).status();    \
  lhs = std::move(holder).value()

#define ASSIGN_OR_RETURN(lhs, expr) \
  LOCATOR_ASSIGN_OR_RETURN_IMPL_(   \
      LOCATOR_STATUS_CONCAT_(locator_status_or_, __LINE__), lhs, expr)

#endif  // LOCATOR_COMMON_STATUS_MACROS_H_
