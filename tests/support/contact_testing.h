// A test helper shared by the contact and partition tests: two contacts the same to the bit.
#pragma once

#include <collide2d/query.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace collide2d::testing {

// The angle between two directions, in [0, pi], without the rounding of acos near 0.
inline double angle_between(const Vec2& u, const Vec2& v) {
  return std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.dot(v));
}

// The same separation, normal, points and manifold, each point with its separation and feature id;
// of two empty contacts (Contact::beyond), the separation alone, all that an empty contact holds.
inline void expect_same_contact(const Contact& x, const Contact& y, const std::string& what) {
  EXPECT_EQ(x.separation, y.separation) << what;
  if (x.empty() && y.empty()) return;
  EXPECT_EQ(x.normal, y.normal) << what;
  EXPECT_EQ(x.point_a, y.point_a) << what;
  EXPECT_EQ(x.point_b, y.point_b) << what;
  ASSERT_EQ(x.manifold_size, y.manifold_size) << what;
  for (const int k : {0, 1}) {
    if (k >= x.manifold_size) break;
    const ContactPoint& p = x.manifold[static_cast<std::size_t>(k)];
    const ContactPoint& q = y.manifold[static_cast<std::size_t>(k)];
    EXPECT_EQ(p.point_a, q.point_a) << what << ", manifold point " << k;
    EXPECT_EQ(p.point_b, q.point_b) << what << ", manifold point " << k;
    EXPECT_EQ(p.separation, q.separation) << what << ", manifold point " << k;
    EXPECT_EQ(p.id, q.id) << what << ", manifold point " << k;
  }
}

}  // namespace collide2d::testing
