/// @file
/// collide2d: exact 2D collision detection between oriented rectangles, ellipses and circles.
/// This header includes every public header; link collide2d::collide2d (CMake) or
/// `pkg-config --libs collide2d`.
#pragma once

#include <collide2d/aabb_tree.h>
#include <collide2d/batch.h>
#include <collide2d/broad_phase.h>
#include <collide2d/chain.h>
#include <collide2d/function_ref.h>
#include <collide2d/kernels.h>
#include <collide2d/partition.h>
#include <collide2d/query.h>
#include <collide2d/ray_cast.h>
#include <collide2d/replay.h>
#include <collide2d/shapes.h>
#include <collide2d/time_of_impact.h>
#include <collide2d/version.h>
#include <collide2d/world.h>
