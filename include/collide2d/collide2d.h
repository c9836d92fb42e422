/// @file
/// collide2d: exact 2D collision detection between circles, ellipses, rectangles, capsules, convex
/// polygons and segments. This header includes the library's public headers (shapes, queries and
/// the World); link collide2d::collide2d (CMake) or `pkg-config --libs collide2d`. The modules
/// beside it have headers and targets of their own: the recorder (collide2d/replay.h,
/// collide2d::replay), the World split by regions (collide2d/partition.h, collide2d::partition) and
/// over MPI ranks (collide2d/distributed.h, collide2d::distributed).
#pragma once

#include <collide2d/aabb_tree.h>
#include <collide2d/area.h>
#include <collide2d/batch.h>
#include <collide2d/broad_phase.h>
#include <collide2d/chain.h>
#include <collide2d/function_ref.h>
#include <collide2d/kernels.h>
#include <collide2d/mover.h>
#include <collide2d/query.h>
#include <collide2d/ray_cast.h>
#include <collide2d/shapes.h>
#include <collide2d/time_of_impact.h>
#include <collide2d/version.h>
#include <collide2d/world.h>
