/**
 * @file
 * libbezsurf: rectangular (tensor-product) Bezier surface patches.
 *
 * The one header users include. The API is split into topical headers:
 *   bezsurf/core.h     status codes, version, views, patches, evaluation
 *   bezsurf/ops.h      exact operations: subdivision, elevation, hodographs, iso-curves, constructions
 *   bezsurf/surface.h  multi-patch surfaces
 *   bezsurf/io.h       the .bpt text format, the built-in tea set
 *   bezsurf/continuity.h  shared and open edges of a surface, continuity across them
 *   bezsurf/mesh.h     tessellation into triangle meshes, mesh export
 *   bezsurf/bspline.h  B-spline and NURBS surfaces cut into Bezier patches (from 1.1)
 *   bezsurf/query.h    geometric queries: curvature (from 1.1)
 * Everything declared here is part of the stable C ABI (SONAME libbezsurf.so.1).
 */
#ifndef BEZSURF_H
#define BEZSURF_H

#include "bezsurf/version.h"
#include "bezsurf/core.h"
#include "bezsurf/ops.h"
#include "bezsurf/surface.h"
#include "bezsurf/io.h"
#include "bezsurf/continuity.h"
#include "bezsurf/mesh.h"
#include "bezsurf/bspline.h"
#include "bezsurf/query.h"
#include "bezsurf/model.h"

#endif
