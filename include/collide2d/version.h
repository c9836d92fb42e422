/// @file
/// The version of collide2d these headers belong to.
///
/// Versioning follows Semantic Versioning: a release that changes or removes a public declaration
/// (docs/api.txt) raises MAJOR (MINOR while MAJOR is 0); one that only adds raises
/// MINOR; one that changes neither raises PATCH. A result may change by rounding in any release that
/// says so in CHANGELOG.md; the documented accuracy bounds hold in every release.
#pragma once

#define COLLIDE2D_VERSION_MAJOR 0
#define COLLIDE2D_VERSION_MINOR 4
#define COLLIDE2D_VERSION_PATCH 0
/// MAJOR * 10000 + MINOR * 100 + PATCH, for comparisons in the preprocessor.
#define COLLIDE2D_VERSION (COLLIDE2D_VERSION_MAJOR * 10000 + COLLIDE2D_VERSION_MINOR * 100 + COLLIDE2D_VERSION_PATCH)
/// "MAJOR.MINOR.PATCH".
#define COLLIDE2D_VERSION_STRING "0.4.0"
