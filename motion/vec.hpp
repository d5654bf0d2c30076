// Points and vectors of the motion kernel, axes, and the G17/G18/G19 planes.
//
// Units: the kernel never converts units. Lengths are in the program's length unit after the
// interpreter has applied G20/G21 (normally mm) and are *geometric* coordinates: on a lathe the
// interpreter turns diameter-programmed X into the radius before calling the kernel
// (semantics.md §2.7 "X values in diameter throughout" is a programming convention, not geometry).
#pragma once

#include <cmath>

namespace kerf::motion {

struct Vec3 {
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;

    constexpr Vec3& operator+=(Vec3 o) { x += o.x; y += o.y; z += o.z; return *this; }
    constexpr Vec3& operator-=(Vec3 o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
    constexpr Vec3& operator*=(double k) { x *= k; y *= k; z *= k; return *this; }
    friend constexpr Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
    friend constexpr Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
    friend constexpr Vec3 operator-(Vec3 a) { return {-a.x, -a.y, -a.z}; }
    friend constexpr Vec3 operator*(Vec3 a, double k) { return {a.x * k, a.y * k, a.z * k}; }
    friend constexpr Vec3 operator*(double k, Vec3 a) { return a * k; }
    friend constexpr Vec3 operator/(Vec3 a, double k) { return {a.x / k, a.y / k, a.z / k}; }
    friend constexpr bool operator==(Vec3, Vec3) = default;   // exact; use distance() for tolerance
};

constexpr double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
constexpr Vec3 cross(Vec3 a, Vec3 b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
constexpr double norm2(Vec3 a) { return dot(a, a); }
inline double norm(Vec3 a) { return std::sqrt(norm2(a)); }
inline double distance(Vec3 a, Vec3 b) { return norm(b - a); }
// a + t·(b − a); t = 0 gives a, t = 1 gives b exactly.
constexpr Vec3 lerp(Vec3 a, Vec3 b, double t) {
    return t == 1.0 ? b : Vec3{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t};
}
// Component-wise absolute value (per-axis travel of a move).
inline Vec3 abs_components(Vec3 a) { return {std::fabs(a.x), std::fabs(a.y), std::fabs(a.z)}; }
inline bool is_finite(Vec3 a) { return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z); }

// The three linear axes. (Rotary and extra axes are handled by the span-based time functions.)
enum class Axis { x, y, z };

constexpr double get(Vec3 v, Axis a) { return a == Axis::x ? v.x : a == Axis::y ? v.y : v.z; }
constexpr void set(Vec3& v, Axis a, double value) {
    (a == Axis::x ? v.x : a == Axis::y ? v.y : v.z) = value;
}
constexpr char axis_letter(Axis a) { return a == Axis::x ? 'X' : a == Axis::y ? 'Y' : 'Z'; }

// Plane selection, group 16 (semantics.md §3):
//   G17  xy: first X, second Y, normal Z
//   G18  zx: first Z, second X, normal Y   (FANUC: the G18 plane is Z-X, *not* X-Z)
//   G19  yz: first Y, second Z, normal X
// Each (first, second, normal) is a cyclic permutation of (X, Y, Z), so every plane frame is
// right-handed: first × second = +normal. Consequently a positive angle from first toward second
// is counter-clockwise seen from the positive end of the normal axis looking toward its negative
// end, which is exactly the G03 direction of semantics.md §3 ("viewed from the positive end of
// the axis perpendicular to the plane: G17 from +Z, G18 from +Y, G19 from +X"). G02 (clockwise)
// is a negative angle in every plane. (tests/motion/test_vec.cpp checks this with cross products.)
enum class Plane { xy, zx, yz };

constexpr int g_code(Plane p) { return p == Plane::xy ? 17 : p == Plane::zx ? 18 : 19; }

struct PlaneAxes {
    Axis first;
    Axis second;
    Axis normal;
};

constexpr PlaneAxes plane_axes(Plane p) {
    switch (p) {
    case Plane::xy: return {Axis::x, Axis::y, Axis::z};
    case Plane::zx: return {Axis::z, Axis::x, Axis::y};
    case Plane::yz: return {Axis::y, Axis::z, Axis::x};
    }
    return {Axis::x, Axis::y, Axis::z};
}

// Coordinates of a point or vector in a plane's frame.
struct PlanePoint {
    double first = 0.0;
    double second = 0.0;
    double normal = 0.0;
    friend constexpr bool operator==(PlanePoint, PlanePoint) = default;
};

constexpr PlanePoint to_plane(Vec3 v, Plane p) {
    const PlaneAxes a = plane_axes(p);
    return {get(v, a.first), get(v, a.second), get(v, a.normal)};
}

constexpr Vec3 from_plane(PlanePoint q, Plane p) {
    const PlaneAxes a = plane_axes(p);
    Vec3 v;
    set(v, a.first, q.first);
    set(v, a.second, q.second);
    set(v, a.normal, q.normal);
    return v;
}

// Unit vector of the plane's normal axis (+Z for G17, +Y for G18, +X for G19).
constexpr Vec3 plane_normal(Plane p) { return from_plane({0.0, 0.0, 1.0}, p); }

}  // namespace kerf::motion
