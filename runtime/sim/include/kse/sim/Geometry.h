#pragma once
// Plane geometry of the simulation: field frame in metres and radians, x towards the away
// team's goal in the first half, y to the left, angles counter-clockwise.

#include <cmath>

namespace kse::sim {

constexpr double kPi = 3.14159265358979323846;

inline double NormalizeAngle(double angle) {
	angle = std::fmod(angle + kPi, 2 * kPi);
	if (angle < 0) angle += 2 * kPi;
	return angle - kPi;
}

inline double Clamp(double value, double low, double high) { return value < low ? low : (value > high ? high : value); }

struct Vec2 {
	double x = 0;
	double y = 0;

	Vec2 operator+(Vec2 o) const { return {x + o.x, y + o.y}; }
	Vec2 operator-(Vec2 o) const { return {x - o.x, y - o.y}; }
	Vec2 operator*(double s) const { return {x * s, y * s}; }
	Vec2& operator+=(Vec2 o) { x += o.x; y += o.y; return *this; }
	Vec2& operator-=(Vec2 o) { x -= o.x; y -= o.y; return *this; }
	double Dot(Vec2 o) const { return x * o.x + y * o.y; }
	double Norm() const { return std::hypot(x, y); }
	double Angle() const { return std::atan2(y, x); }
	Vec2 Rotated(double angle) const {
		const double c = std::cos(angle), s = std::sin(angle);
		return {c * x - s * y, s * x + c * y};
	}
	Vec2 Normalized() const {
		const double n = Norm();
		return n > 0 ? Vec2{x / n, y / n} : Vec2{1, 0};
	}
};

inline Vec2 FromPolar(double length, double angle) { return {length * std::cos(angle), length * std::sin(angle)}; }

struct Pose2 {
	double x = 0;
	double y = 0;
	double theta = 0;

	Vec2 Position() const { return {x, y}; }
	/** A point of this pose's frame in the frame the pose is given in. */
	Vec2 ToOuter(Vec2 local) const { return Position() + local.Rotated(theta); }
	/** A point of the outer frame in this pose's frame. */
	Vec2 ToLocal(Vec2 outer) const { return (outer - Position()).Rotated(-theta); }
	Pose2 Moved(Vec2 local, double turn) const {
		const Vec2 p = ToOuter(local);
		return {p.x, p.y, NormalizeAngle(theta + turn)};
	}
};

/**
 * Whether a vector is certainly longer (shorter) than a length, told from its squared length,
 * without the hypot of Norm(): the margin of a billionth is far wider than the rounding of
 * either, so where these say yes, Norm() compared with the length says the same. Where they say
 * no, it is too close to call and the caller compares Norm() as before; nothing computed
 * changes, only work whose result would have been thrown away is skipped.
 */
inline bool SurelyLonger(Vec2 v, double length) { return v.x * v.x + v.y * v.y > length * length * (1 + 1e-9); }
inline bool SurelyShorter(Vec2 v, double length) { return v.x * v.x + v.y * v.y < length * length * (1 - 1e-9); }

/** Closest point of the segment a-b to p. */
inline Vec2 ClosestOnSegment(Vec2 a, Vec2 b, Vec2 p) {
	const Vec2 ab = b - a;
	const double length2 = ab.Dot(ab);
	if (length2 <= 0) return a;
	return a + ab * Clamp((p - a).Dot(ab) / length2, 0.0, 1.0);
}

}  // namespace kse::sim
