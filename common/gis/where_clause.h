// CheckPlainWhereClause: whether an attribute filter (a spec's where=) is a
// plain comparison of the layer's fields and literals, so that a Reload
// request can filter without running SQL of its choosing.
//
// GDAL hands a GeoPackage's filter to SQLite as the WHERE of its SELECT, so
// a free where= could call SQL functions (load_extension, SpatiaLite's
// BlobFromFile, GDAL's own) or read other tables and attached databases by
// sub-select. The grammar accepted here has neither function calls nor
// sub-selects, and both OGR SQL and SQLite read it alike:
//   expr      := and {OR and}
//   and       := not {AND not}
//   not       := NOT not | predicate
//   predicate := sum [ (= | != | <> | < | <= | > | >=) sum
//                    | [NOT] BETWEEN sum AND sum
//                    | [NOT] IN '(' sum {',' sum} ')'
//                    | [NOT] LIKE sum [ESCAPE sum]
//                    | IS [NOT] NULL ]
//   sum       := product {(+ | -) product}
//   product   := unary {(* | / | %) unary}
//   unary     := (+ | -) unary | NUMBER | 'STRING' | NULL | FIELD
//                | '(' expr ')'
// FIELD is a name ([A-Za-z_][A-Za-z0-9_]*, not a keyword) or a
// "double-quoted" one; keywords are case-insensitive; '' and "" escape a
// quote; comments (-- and /*) are refused. At most kMaxWhereBytes bytes, nested
// at most kMaxWhereNesting deep.
//
// Thread-safety: a free function.

#ifndef LOCATOR_COMMON_GIS_WHERE_CLAUSE_H_
#define LOCATOR_COMMON_GIS_WHERE_CLAUSE_H_

#include <cstddef>
#include <string_view>

#include "locator/status.h"

namespace locator::gis {

inline constexpr size_t kMaxWhereBytes = 4096;
inline constexpr int kMaxWhereNesting = 32;

// OK when `where` is in the grammar above; else InvalidArgument naming the
// byte offset and what was found there.
Status CheckPlainWhereClause(std::string_view where);

}  // namespace locator::gis

#endif  // LOCATOR_COMMON_GIS_WHERE_CLAUSE_H_
