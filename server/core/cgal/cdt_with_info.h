// CdtWithInfo: CGAL's constrained Delaunay triangulation on exact
// predicates (and inexact constructions) whose vertices and faces carry
// the caller's info, for the builders that triangulate a boundary, a grid's
// domain or a clipped patch. `IntersectionTag` says what CGAL does where
// constraints cross (CGAL::Default: they must not cross where the crossing
// would need a construction).
//
// Thread-safety: as CGAL's triangulations (one thread per triangulation).

#ifndef LOCATOR_CORE_CGAL_CDT_WITH_INFO_H_
#define LOCATOR_CORE_CGAL_CDT_WITH_INFO_H_

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Constrained_triangulation_face_base_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_data_structure_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

namespace locator {

using CdtKernel = CGAL::Exact_predicates_inexact_constructions_kernel;

template <class VertexInfo, class FaceInfo,
          class IntersectionTag = CGAL::Default>
using CdtWithInfo = CGAL::Constrained_Delaunay_triangulation_2<
    CdtKernel,
    CGAL::Triangulation_data_structure_2<
        CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, CdtKernel>,
        CGAL::Constrained_triangulation_face_base_2<
            CdtKernel,
            CGAL::Triangulation_face_base_with_info_2<FaceInfo, CdtKernel>>>,
    IntersectionTag>;

}  // namespace locator

#endif  // LOCATOR_CORE_CGAL_CDT_WITH_INFO_H_
