// collide2d: exact 2D collision detection between oriented rectangles, ellipses and circles.
// Include this one header; link collide2d::collide2d.
#pragma once

#include "broadphase/broad_phase.h"
#include "engine/world.h"
#include "narrowphase/overlap_batch.h"
#include "narrowphase/query.h"
#include "narrowphase/ray_cast.h"
#include "narrowphase/time_of_impact.h"
#include "shapes/shapes.h"
