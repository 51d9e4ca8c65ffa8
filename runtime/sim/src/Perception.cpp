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
		if ((centre - from).Norm() >= distance) continue;
		if ((ClosestOnSegment(from, to, centre) - centre).Norm() < kOcclusionRadius) return true;
	}
	return false;
}

Vec2 Noisy(Vec2 relative, Random& random, double base_sigma, double relative_sigma) {
	const double distance = relative.Norm();
	const double measured = std::max(0.0, distance + random.Gaussian(base_sigma + relative_sigma * distance));
	const double bearing = relative.Angle() + random.Gaussian(0.02);
	return FromPolar(measured, bearing);
}

}  // namespace

bool InView(const Body& body, bool top_camera, Vec2 point, double low, double high) {
	const Vec2 relative = body.pose.ToLocal(point);
	const double bearing = NormalizeAngle(relative.Angle() - body.head_yaw);
	if (std::fabs(bearing) > nao::kHorizontalFov / 2) return false;
	const double height = top_camera ? nao::kTopCameraHeight : nao::kBottomCameraHeight;
	const double optical_axis = body.head_pitch + (top_camera ? nao::kTopCameraPitch : nao::kBottomCameraPitch);
	// depth along the optical axis' horizontal direction
	const double depth = std::max(1e-6, relative.Norm() * std::cos(bearing));
	// angles below the horizon of the object's top and bottom
	const double below_top = std::atan2(height - high, depth);
	const double below_bottom = std::atan2(height - low, depth);
	const double half = nao::kVerticalFov / 2;
	return below_bottom >= optical_axis - half && below_top <= optical_axis + half;
}

Image Look(const World& world, int index, bool top_camera, Random& random) {
	Image image;
	image.top = top_camera;
	const Body& body = world.bodies[static_cast<std::size_t>(index)];
	if (!body.Upright()) return image;
	const Vec2 eye = body.pose.Position();

	const Vec2 ball = world.ball.position;
	const double ball_distance = (ball - eye).Norm();
	const double ball_range = top_camera ? kBallRange : kBallRangeBottom;
	if (ball_distance <= ball_range &&
	    InView(body, top_camera, ball, 0, 2 * field::kBallRadius) &&
	    !Occluded(world, index, eye, ball, -1) &&
	    random.Chance(kBallDetection - 0.15 * ball_distance / kBallRange)) {
		image.seen.push_back({Sighting::Kind::Ball, Noisy(body.pose.ToLocal(ball), random, 0.01, 0.04), -1});
	}
	for (int side : {1, -1}) {
		for (int post : {1, -1}) {
			const Vec2 where{side * field::kPostX, post * field::kPostY};
			if ((where - eye).Norm() <= kPostRange && InView(body, top_camera, where, 0, field::kPostHeight) &&
			    random.Chance(0.9)) {
				image.seen.push_back({Sighting::Kind::Post, Noisy(body.pose.ToLocal(where), random, 0.05, 0.05), -1});
			}
		}
	}
	for (std::size_t i = 0; i < world.bodies.size(); ++i) {
		const Body& other = world.bodies[i];
		const int other_index = static_cast<int>(i);
		if (other_index == index || !other.on_field) continue;
		const Vec2 where = other.pose.Position();
		if ((where - eye).Norm() <= kRobotRange && InView(body, top_camera, where, 0, nao::kHeight) &&
		    !Occluded(world, index, eye, where, other_index) && random.Chance(0.8)) {
			image.seen.push_back({Sighting::Kind::Robot, Noisy(body.pose.ToLocal(where), random, 0.05, 0.08), other_index});
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
