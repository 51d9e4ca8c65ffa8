#include <kse/sim/Perception.h>

#include <cmath>

namespace kse::sim {

namespace camera {

namespace {

constexpr double kBallDetection = 0.95;  // a ball in view and range is found in most images
constexpr double kOcclusionRadius = nao::kBodyRadius;

bool Occluded(const World& world, int viewer, Vec2 from, Vec2 to, int target) {
	const double distance = (to - from).Norm();
	for (std::size_t i = 0; i < world.bodies.size(); ++i) {
		const int index = static_cast<int>(i);
		if (index == viewer || index == target || !world.bodies[i].on_field) continue;
		const Vec2 centre = world.bodies[i].pose.Position();
		if (SurelyLonger(centre - from, distance) || (centre - from).Norm() >= distance) continue;
		const Vec2 miss = ClosestOnSegment(from, to, centre) - centre;
		if (!SurelyLonger(miss, kOcclusionRadius) && miss.Norm() < kOcclusionRadius) return true;
	}
	return false;
}

Vec2 Noisy(Vec2 relative, Random& random, double base_sigma, double relative_sigma) {
	const double distance = relative.Norm();
	const double measured = std::max(0.0, distance + random.Gaussian(base_sigma + relative_sigma * distance));
	const double bearing = relative.Angle() + random.Gaussian(0.02);
	return FromPolar(measured, bearing);
}

/**
 * A robot's camera for one image: Pose2::ToLocal and InView with the rotation into the robot's
 * frame computed once per image instead of once per thing looked at (the same cos and sin of the
 * same angle, so the same numbers).
 */
class Eye {
public:
	Eye(const Body& body, bool top_camera)
	    : body_(body), top_camera_(top_camera), cos_(std::cos(-body.pose.theta)), sin_(std::sin(-body.pose.theta)) {}

	/** body.pose.ToLocal(outer), as Vec2::Rotated computes it. */
	Vec2 ToLocal(Vec2 outer) const {
		const Vec2 v = outer - body_.pose.Position();
		return {cos_ * v.x - sin_ * v.y, sin_ * v.x + cos_ * v.y};
	}

	bool InView(Vec2 point, double low, double high) const {
		const Vec2 relative = ToLocal(point);
		const double bearing = NormalizeAngle(relative.Angle() - body_.head_yaw);
		if (std::fabs(bearing) > nao::kHorizontalFov / 2) return false;
		const double height = top_camera_ ? nao::kTopCameraHeight : nao::kBottomCameraHeight;
		const double optical_axis = body_.head_pitch + (top_camera_ ? nao::kTopCameraPitch : nao::kBottomCameraPitch);
		// depth along the optical axis' horizontal direction
		const double depth = std::max(1e-6, relative.Norm() * std::cos(bearing));
		// angles below the horizon of the object's bottom and top (the top only when the bottom is in view)
		const double half = nao::kVerticalFov / 2;
		const double below_bottom = std::atan2(height - low, depth);
		if (!(below_bottom >= optical_axis - half)) return false;
		const double below_top = std::atan2(height - high, depth);
		return below_top <= optical_axis + half;
	}

private:
	const Body& body_;
	bool top_camera_;
	double cos_;
	double sin_;
};

}  // namespace

bool InView(const Body& body, bool top_camera, Vec2 point, double low, double high) { return Eye(body, top_camera).InView(point, low, high); }

Image Look(const World& world, int index, bool top_camera, Random& random) {
	Image image;
	image.top = top_camera;
	const Body& body = world.bodies[static_cast<std::size_t>(index)];
	if (!body.Upright()) return image;
	const Vec2 eye = body.pose.Position();
	const Eye camera(body, top_camera);

	// Each test in the order (and with the numbers) it always had; a range surely exceeded
	// skips the hypot of the distance, whose comparison would have failed.
	const Vec2 ball = world.ball.position;
	const double ball_range = top_camera ? kBallRange : kBallRangeBottom;
	if (!SurelyLonger(ball - eye, ball_range)) {
		const double ball_distance = (ball - eye).Norm();
		if (ball_distance <= ball_range &&
		    camera.InView(ball, 0, 2 * field::kBallRadius) &&
		    !Occluded(world, index, eye, ball, -1) &&
		    random.Chance(kBallDetection - 0.15 * ball_distance / kBallRange)) {
			image.seen.push_back({Sighting::Kind::Ball, Noisy(camera.ToLocal(ball), random, 0.01, 0.04), -1});
		}
	}
	for (int side : {1, -1}) {
		for (int post : {1, -1}) {
			const Vec2 where{side * field::kPostX, post * field::kPostY};
			if (!SurelyLonger(where - eye, kPostRange) && (where - eye).Norm() <= kPostRange &&
			    camera.InView(where, 0, field::kPostHeight) && random.Chance(0.9)) {
				image.seen.push_back({Sighting::Kind::Post, Noisy(camera.ToLocal(where), random, 0.05, 0.05), -1});
			}
		}
	}
	for (std::size_t i = 0; i < world.bodies.size(); ++i) {
		const Body& other = world.bodies[i];
		const int other_index = static_cast<int>(i);
		if (other_index == index || !other.on_field) continue;
		const Vec2 where = other.pose.Position();
		if (!SurelyLonger(where - eye, kRobotRange) && (where - eye).Norm() <= kRobotRange &&
		    camera.InView(where, 0, nao::kHeight) && !Occluded(world, index, eye, where, other_index) && random.Chance(0.8)) {
			image.seen.push_back({Sighting::Kind::Robot, Noisy(camera.ToLocal(where), random, 0.05, 0.08), other_index});
		}
	}
	return image;
}

}  // namespace camera

namespace {
constexpr double kBallMemory = 1.0;       // s a ball stays in the model after it was last seen
constexpr double kOdometryNoise = 0.03;   // m of drift per metre walked
constexpr double kTurnNoise = 0.02;       // rad of drift per radian turned
constexpr double kPostCorrection = 0.3;   // share of the error a seen goal post removes
constexpr double kLineCorrection = 0.03;  // share of the error the field lines remove each image
}  // namespace

void RobotSense::Update(const World& world, int index, const Image& image, double now) {
	const Body& body = world.bodies[static_cast<std::size_t>(index)];
	if (has_last_pose_) {
		const double walked = (body.pose.Position() - last_pose_.Position()).Norm();
		const double turned = std::fabs(NormalizeAngle(body.pose.theta - last_pose_.theta));
		position_error_ += Vec2{random_.Gaussian(kOdometryNoise * walked), random_.Gaussian(kOdometryNoise * walked)};
		heading_error_ += random_.Gaussian(kTurnNoise * turned + 0.01 * walked);
	}
	last_pose_ = body.pose;
	has_last_pose_ = true;

	bool post = false;
	for (const auto& sighting : image.seen) {
		if (sighting.kind == Sighting::Kind::Post) post = true;
		if (sighting.kind == Sighting::Kind::Ball) {
			ball_field_ = Estimate(body).ToOuter(sighting.relative);
			// the ball's velocity comes from a filter on a real robot; here its error is modelled
			const double speed = world.ball.velocity.Norm();
			ball_velocity_ = world.ball.velocity + Vec2{random_.Gaussian(0.05 + 0.1 * speed), random_.Gaussian(0.05 + 0.1 * speed)};
			ball_seen_at_ = now;
		}
	}
	if (body.Upright()) {
		const double correction = post ? kPostCorrection : (image.top ? kLineCorrection : 0.0);
		position_error_ = position_error_ * (1 - correction);
		heading_error_ *= 1 - correction;
	}
}

void RobotSense::Kidnapped(double error) {
	position_error_ = {random_.Gaussian(error), random_.Gaussian(error)};
	heading_error_ = random_.Gaussian(error / 2);
	has_last_pose_ = false;
	ball_seen_at_ = -1e9;
}

Pose2 RobotSense::Estimate(const Body& body) const {
	return {body.pose.x + position_error_.x, body.pose.y + position_error_.y, NormalizeAngle(body.pose.theta + heading_error_)};
}

double RobotSense::Confidence() const {
	return Clamp(1.0 - (position_error_.Norm() + 0.5 * std::fabs(heading_error_)) / 0.5, 0.0, 1.0);
}

robot::BallPercept RobotSense::BallPercept(const Body& body, double now) const {
	robot::BallPercept percept;
	const double age = now - ball_seen_at_;
	if (age > kBallMemory || !body.on_field) return percept;
	const Pose2 estimate = Estimate(body);
	const Vec2 predicted = ball_field_ + ball_velocity_ * age;
	const Vec2 relative = estimate.ToLocal(predicted);
	const Vec2 velocity = ball_velocity_.Rotated(-estimate.theta);
	percept.seen = true;
	percept.x = static_cast<float>(relative.x);
	percept.y = static_cast<float>(relative.y);
	percept.vx = static_cast<float>(velocity.x);
	percept.vy = static_cast<float>(velocity.y);
	return percept;
}

}  // namespace kse::sim
