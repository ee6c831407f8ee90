#pragma once
// Small fixed-size vectors for geometry and colour triples.
#include <algorithm>
#include <cmath>
#include <cstddef>

namespace prism {

template <typename T>
struct Vec2 {
  T x{}, y{};
  constexpr Vec2() = default;
  constexpr Vec2(T x_, T y_) : x(x_), y(y_) {}
  constexpr T operator[](std::size_t i) const { return i == 0 ? x : y; }
};

template <typename T>
struct Vec3 {
  T x{}, y{}, z{};
  constexpr Vec3() = default;
  constexpr Vec3(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}
  constexpr explicit Vec3(T s) : x(s), y(s), z(s) {}
  template <typename U>
  constexpr explicit Vec3(const Vec3<U>& v) : x(T(v.x)), y(T(v.y)), z(T(v.z)) {}

  constexpr T operator[](std::size_t i) const { return i == 0 ? x : (i == 1 ? y : z); }
  constexpr T& operator[](std::size_t i) { return i == 0 ? x : (i == 1 ? y : z); }

  constexpr Vec3 operator-() const { return {-x, -y, -z}; }
  constexpr Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
  constexpr Vec3& operator-=(const Vec3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
  constexpr Vec3& operator*=(const Vec3& o) { x *= o.x; y *= o.y; z *= o.z; return *this; }
  constexpr Vec3& operator*=(T s) { x *= s; y *= s; z *= s; return *this; }
  constexpr Vec3& operator/=(T s) { return *this *= T(1) / s; }
  constexpr bool operator==(const Vec3&) const = default;
};

template <typename T> constexpr Vec3<T> operator+(Vec3<T> a, const Vec3<T>& b) { return a += b; }
template <typename T> constexpr Vec3<T> operator-(Vec3<T> a, const Vec3<T>& b) { return a -= b; }
template <typename T> constexpr Vec3<T> operator*(Vec3<T> a, const Vec3<T>& b) { return a *= b; }
template <typename T> constexpr Vec3<T> operator*(Vec3<T> a, T s) { return a *= s; }
template <typename T> constexpr Vec3<T> operator*(T s, Vec3<T> a) { return a *= s; }
template <typename T> constexpr Vec3<T> operator/(Vec3<T> a, T s) { return a /= s; }
template <typename T> constexpr Vec3<T> operator/(const Vec3<T>& a, const Vec3<T>& b) {
  return {a.x / b.x, a.y / b.y, a.z / b.z};
}

template <typename T> constexpr T dot(const Vec3<T>& a, const Vec3<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <typename T> constexpr Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <typename T> T length(const Vec3<T>& a) { return std::sqrt(dot(a, a)); }
template <typename T> constexpr T length_squared(const Vec3<T>& a) { return dot(a, a); }
template <typename T> Vec3<T> normalize(const Vec3<T>& a) { return a / length(a); }
template <typename T> constexpr Vec3<T> min(const Vec3<T>& a, const Vec3<T>& b) {
  return {std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
}
template <typename T> constexpr Vec3<T> max(const Vec3<T>& a, const Vec3<T>& b) {
  return {std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
}
template <typename T> constexpr T max_component(const Vec3<T>& a) { return std::max({a.x, a.y, a.z}); }
template <typename T> constexpr T min_component(const Vec3<T>& a) { return std::min({a.x, a.y, a.z}); }
template <typename T> bool is_finite(const Vec3<T>& a) {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}

using Vec2f = Vec2<float>;
using Vec3f = Vec3<float>;
using Vec3d = Vec3<double>;

}  // namespace prism
