// collide2d: exact 2D collision detection between oriented rectangles, ellipses and circles.
// Include this one header; link collide2d::collide2d.
#pragma once

#include <collide2d/broad_phase.h>
#include <collide2d/world.h>
#include <collide2d/batch.h>
#include <collide2d/query.h>
#include <collide2d/ray_cast.h>
#include <collide2d/time_of_impact.h>
#include <collide2d/shapes.h>
