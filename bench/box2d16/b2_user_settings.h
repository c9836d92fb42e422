// Box2D 2.4.1's settings for the 16-gon baseline (bench/CMakeLists.txt builds Box2D from Debian's
// source package with B2_USER_SETTINGS). Box2D reads this file instead of its defaults; everything
// is as in the defaults except b2_maxPolygonVertices, raised from 8 to 16 so that an ellipse can be
// a 16-gon. The polygon code sizes its arrays and loops by this constant and has no other limit.
#pragma once

#include <stdarg.h>
#include <stdint.h>

#define b2_lengthUnitsPerMeter 1.0f
#define b2_maxPolygonVertices 16

struct B2_API b2BodyUserData {
  uintptr_t pointer = 0;
};
struct B2_API b2FixtureUserData {
  uintptr_t pointer = 0;
};
struct B2_API b2JointUserData {
  uintptr_t pointer = 0;
};

B2_API void* b2Alloc_Default(int32 size);
B2_API void b2Free_Default(void* mem);
B2_API void b2Log_Default(const char* string, va_list args);

inline void* b2Alloc(int32 size) { return b2Alloc_Default(size); }
inline void b2Free(void* mem) { b2Free_Default(mem); }
inline void b2Log(const char* string, ...) {
  va_list args;
  va_start(args, string);
  b2Log_Default(string, args);
  va_end(args);
}
