#include <kse/sim/World.h>

#include <algorithm>
#include <cmath>

namespace kse::sim {

namespace {

// Standing kicks take the legs for their whole duration; in-walk kicks are quick and short.
constexpr KickSpec kKicks[] = {
	{"KickForwardLeft", 1.5, 0.6, {0.13, 0.04}, 0.09, 0.0, 1.6, 4.5, 0.07, false},
	{"KickForwardRight", 1.5, 0.6, {0.13, -0.04}, 0.09, 0.0, 1.6, 4.5, 0.07, false},
	{"KickSideLeft", 1.2, 0.5, {0.12, -0.02}, 0.09, 1.4, 1.0, 2.5, 0.12, false},
	{"KickSideRight", 1.2, 0.5, {0.12, 0.02}, 0.09, -1.4, 1.0, 2.5, 0.12, false},
	{"InWalkKickLeft", 0.4, 0.25, {0.14, 0.04}, 0.08, 0.0, 1.0, 2.5, 0.12, true},
	{"InWalkKickRight", 0.4, 0.25, {0.14, -0.04}, 0.08, 0.0, 1.0, 2.5, 0.12, true},
};

constexpr double kDiveFall = 0.4;      // s until the body lies at full reach
constexpr double kDiveLying = 2.0;     // s after the start the goalkeeper begins to get up
constexpr double kDiveDuration = 4.0;  // s until it stands again
constexpr double kFallenTime = 1.0;
constexpr double kGetUpTime = 3.0;
constexpr double kPoseTime = 0.5;

constexpr double kBallRestitutionFeet = 0.35;
constexpr double kBallRestitutionLying = 0.2;
constexpr double kBallRestitutionPost = 0.5;
constexpr double kBallRestitutionNet = 0.1;
constexpr double kBallRestitutionWall = 0.3;

double Approach(double value, double target, double step) {
	if (value < target) return std::min(target, value + step);
	return std::max(target, value - step);
}

struct Segment {
	Vec2 a;
	Vec2 b;
	double radius;
	double restitution;
};

/** The parts of a body the ball can meet, field frame. */
int BodySegments(const Body& body, Segment out[2]) {
	if (!body.on_field) return 0;
	const Pose2& p = body.pose;
	if (body.Fallen()) {
		out[0] = {p.ToOuter({-0.45, 0}), p.Position(), nao::kLyingRadius, kBallRestitutionLying};
		return 1;
	}
	out[0] = {p.ToOuter({0, -nao::kFeetHalfWidth}), p.ToOuter({0, nao::kFeetHalfWidth}), nao::kFeetRadius, kBallRestitutionFeet};
	const double extent = body.DiveExtent();
	if (extent <= 0) return 1;
	out[1] = {p.Position(), p.ToOuter({0, body.dive_side * extent}), nao::kLyingRadius, kBallRestitutionLying};
	return 2;
}

}  // namespace

const char* ToString(Motion motion) {
	switch (motion) {
		case Motion::Stand: return "stand";
		case Motion::Walk: return "walk";
		case Motion::Kick: return "kick";
		case Motion::Dive: return "dive";
		case Motion::Fallen: return "fallen";
		case Motion::GettingUp: return "getting-up";
		case Motion::Pose: return "pose";
	}
	return "?";
}

const KickSpec* FindKick(const std::string& name) {
	for (const auto& kick : kKicks) {
		if (name == kick.name) return &kick;
	}
	return nullptr;
}

double Body::DiveExtent() const {
	if (motion != Motion::Dive || motion_time >= kDiveLying) return 0;
	return nao::kDiveReach * std::min(1.0, motion_time / kDiveFall);
}

void Body::Command(const robot::MotionCommands& commands) {
	if (commands.walk) {
		walk_mode = WalkMode::Velocity;
		walk_velocity = {commands.vx, commands.vy};
		walk_turn = commands.vtheta;
	} else if (commands.walk_to) {
		walk_mode = WalkMode::Target;
		walk_target = pose.Moved({commands.to_x, commands.to_y}, commands.to_theta);
	}
	if (commands.head) {
		head_yaw_target = Clamp(commands.yaw, -nao::kMaxHeadYaw, nao::kMaxHeadYaw);
		head_pitch_target = Clamp(commands.pitch, nao::kMinHeadPitch, nao::kMaxHeadPitch);
	}
	for (const auto& action : commands.actions) {
		if (!LegsFree() && motion != Motion::Pose) break;
		if (const KickSpec* spec = FindKick(action)) {
			motion = Motion::Kick;
			kick = spec;
			kick_done = false;
			motion_time = 0;
			if (!spec->in_walk) {
				velocity = {};
				turn_rate = 0;
			}
			walk_mode = spec->in_walk ? walk_mode : WalkMode::None;
			break;
		}
		if (action == "goalieLeft" || action == "goalieRight") {
			motion = Motion::Dive;
			dive_side = action == "goalieLeft" ? 1 : -1;
			motion_time = 0;
			velocity = {};
			turn_rate = 0;
			walk_mode = WalkMode::None;
			break;
		}
		if (action == "InitPose" || action == "Stand") {
			motion = Motion::Pose;
			motion_time = 0;
			velocity = {};
			turn_rate = 0;
			walk_mode = WalkMode::None;
		}
		// unknown actions are ignored, as a real motion engine ignores unknown motion names
	}
}

void Body::Place(const Pose2& where) {
	pose = where;
	velocity = {};
	turn_rate = 0;
	motion = Motion::Stand;
	motion_time = 0;
	walk_mode = WalkMode::None;
	pushing_time = 0;
}

Vec2 World::KickVelocity(double distance, double direction) {
	// the ball stops where v²/2a = distance
	return FromPolar(std::sqrt(2.0 * field::kBallDeceleration * distance), direction);
}

void World::Step(double dt) {
	events_.clear();
	for (std::size_t i = 0; i < bodies.size(); ++i) {
		Body& body = bodies[i];
		if (!body.on_field) continue;
		MoveBody(body, dt);
		if (body.motion == Motion::Kick && !body.kick_done && body.motion_time >= body.kick->contact) {
			body.kick_done = true;
			Kick(static_cast<int>(i), body);
		}
	}
	CollideBodies(dt);
	MoveBall(dt);
	CollideBallWithBodies();
	CollideBallWithGoals();
}

void World::MoveBody(Body& body, double dt) {
	body.motion_time += dt;
	if (!body.Fallen()) {
		body.head_yaw = Approach(body.head_yaw, body.head_yaw_target, nao::kHeadSpeed * dt);
		body.head_pitch = Approach(body.head_pitch, body.head_pitch_target, nao::kHeadSpeed * dt);
	}
	switch (body.motion) {
		case Motion::Kick:
			if (body.motion_time >= body.kick->duration) {
				body.motion = Motion::Stand;
				body.motion_time = 0;
			}
			if (!body.kick->in_walk) return;
			break;
		case Motion::Dive:
			if (body.motion_time >= kDiveDuration) {
				body.motion = Motion::Stand;
				body.motion_time = 0;
			}
			return;
		case Motion::Fallen:
			if (body.motion_time >= kFallenTime) {
				body.motion = Motion::GettingUp;
				body.motion_time = 0;
			}
			return;
		case Motion::GettingUp:
			if (body.motion_time >= kGetUpTime) {
				body.motion = Motion::Stand;
				body.motion_time = 0;
			}
			return;
		case Motion::Pose:
			if (body.motion_time >= kPoseTime) {
				body.motion = Motion::Stand;
				body.motion_time = 0;
			}
			return;
		case Motion::Stand:
		case Motion::Walk:
			break;
	}

	// The walk: a request normalised to the walk's limits, within an ellipsoid as walk engines do.
	double fx = 0, fy = 0, ft = 0;
	if (body.walk_mode == Body::WalkMode::Velocity) {
		fx = Clamp(body.walk_velocity.x, -1, 1);
		fy = Clamp(body.walk_velocity.y, -1, 1);
		ft = Clamp(body.walk_turn, -1, 1);
	} else if (body.walk_mode == Body::WalkMode::Target) {
		const Vec2 local = body.pose.ToLocal(body.walk_target.Position());
		const double turn = NormalizeAngle(body.walk_target.theta - body.pose.theta);
		if (local.Norm() < 0.03 && std::fabs(turn) < 0.05) {
			body.walk_mode = Body::WalkMode::None;
		} else {
			fx = Clamp(2.0 * local.x / (local.x >= 0 ? nao::kMaxForward : nao::kMaxBackward), -1, 1);
			fy = Clamp(2.0 * local.y / nao::kMaxSideways, -1, 1);
			ft = Clamp(2.0 * turn / nao::kMaxTurn, -1, 1);
		}
	}
	const double size = std::sqrt(fx * fx + fy * fy + ft * ft);
	if (size > 1) {
		fx /= size;
		fy /= size;
		ft /= size;
	}
	const Vec2 target{fx * (fx >= 0 ? nao::kMaxForward : nao::kMaxBackward), fy * nao::kMaxSideways};
	const double linear_step = nao::kLinearAcceleration * dt;
	body.velocity.x = Approach(body.velocity.x, target.x, linear_step);
	body.velocity.y = Approach(body.velocity.y, target.y, linear_step);
	body.turn_rate = Approach(body.turn_rate, ft * nao::kMaxTurn, nao::kAngularAcceleration * dt);

	const bool moving = body.velocity.Norm() > 1e-4 || std::fabs(body.turn_rate) > 1e-4;
	if (body.motion != Motion::Kick) body.motion = moving ? Motion::Walk : Motion::Stand;
	if (!moving) return;
	body.pose = body.pose.Moved(body.velocity * dt, body.turn_rate * dt);
	// a walking Nao falls now and then, more often at full speed
	const double effort = std::min(1.0, body.velocity.Norm() / nao::kMaxForward);
	if (random_.Chance(0.002 * effort * dt)) {
		body.motion = Motion::Fallen;
		body.motion_time = 0;
		body.velocity = {};
		body.turn_rate = 0;
		events_.push_back({PhysicsEvent::Type::Fall, static_cast<int>(&body - bodies.data()), "walking", 0});
	}
	body.pose.x = Clamp(body.pose.x, -field::kCarpetHalfLength, field::kCarpetHalfLength);
	body.pose.y = Clamp(body.pose.y, -field::kCarpetHalfWidth, field::kCarpetHalfWidth);
}

void World::Kick(int index, Body& body) {
	const KickSpec& spec = *body.kick;
	const Vec2 local = body.pose.ToLocal(ball.position);
	const Vec2 offset = local - spec.sweet_spot;
	const double miss = offset.Norm() / spec.reach;
	if (miss > 1.0 || ball.velocity.Norm() > 1.5) {
		events_.push_back({PhysicsEvent::Type::MissedKick, index, spec.name, 0});
		return;
	}
	// a ball off the sweet spot goes less far and is deflected away from the foot's centre
	const double distance = Clamp(spec.max_distance - (spec.max_distance - spec.min_distance) * miss + random_.Gaussian(0.2),
	                              spec.min_distance, spec.max_distance);
	const double direction = body.pose.theta + spec.direction + random_.Gaussian(spec.direction_sigma) + 1.5 * offset.y * (1 - std::fabs(std::sin(spec.direction)));
	ball.velocity = KickVelocity(distance, direction);
	last_touch_ = index;
	events_.push_back({PhysicsEvent::Type::Kick, index, spec.name, distance});
}

void World::MoveBall(double dt) {
	const double speed = ball.velocity.Norm();
	if (speed <= 0) return;
	const double slower = speed - field::kBallDeceleration * dt;
	if (slower < 0.005) {
		// the last bit of rolling before it stops
		ball.position += ball.velocity * (0.5 * speed / field::kBallDeceleration);
		ball.velocity = {};
		return;
	}
	ball.position += ball.velocity * dt;
	ball.velocity = ball.velocity * (slower / speed);

	// the carpet's edge: boards around the carpet, as in a lab
	const double limit_x = field::kCarpetHalfLength - field::kBallRadius;
	const double limit_y = field::kCarpetHalfWidth - field::kBallRadius;
	if (std::fabs(ball.position.x) > limit_x) {
		ball.position.x = std::copysign(limit_x, ball.position.x);
		ball.velocity.x = -kBallRestitutionWall * ball.velocity.x;
	}
	if (std::fabs(ball.position.y) > limit_y) {
		ball.position.y = std::copysign(limit_y, ball.position.y);
		ball.velocity.y = -kBallRestitutionWall * ball.velocity.y;
	}
}

namespace {

/** Pushes the ball out of a round obstacle and reflects it; true when they met. */
bool Bounce(Ball& ball, Vec2 closest, double radius, double restitution, Vec2 obstacle_velocity) {
	const Vec2 away = ball.position - closest;
	const double contact = radius + field::kBallRadius;
	if (SurelyLonger(away, contact)) return false;  // apart: the hypot below would say so too
	const double distance = away.Norm();
	if (distance >= contact) return false;
	const Vec2 normal = distance > 1e-9 ? away * (1.0 / distance) : Vec2{1, 0};
	ball.position = closest + normal * contact;
	const double approaching = (ball.velocity - obstacle_velocity).Dot(normal);
	if (approaching < 0) ball.velocity -= normal * ((1 + restitution) * approaching);
	return true;
}

}  // namespace

void World::CollideBallWithBodies() {
	for (std::size_t i = 0; i < bodies.size(); ++i) {
		Segment segments[2];
		const int count = BodySegments(bodies[i], segments);
		const Vec2 velocity = bodies[i].Upright() ? bodies[i].FieldVelocity() : Vec2{};
		for (int s = 0; s < count; ++s) {
			const Vec2 closest = ClosestOnSegment(segments[s].a, segments[s].b, ball.position);
			if (Bounce(ball, closest, segments[s].radius, segments[s].restitution, velocity)) {
				last_touch_ = static_cast<int>(i);
				events_.push_back({PhysicsEvent::Type::Touch, static_cast<int>(i), "", 0});
			}
		}
	}
}

void World::CollideBodies(double dt) {
	std::vector<bool> pushing(bodies.size(), false);
	for (std::size_t i = 0; i < bodies.size(); ++i) {
		for (std::size_t j = i + 1; j < bodies.size(); ++j) {
			Body& a = bodies[i];
			Body& b = bodies[j];
			if (!a.on_field || !b.on_field) continue;
			const Vec2 between = b.pose.Position() - a.pose.Position();
			const double contact = 2 * nao::kBodyRadius;
			if (SurelyLonger(between, contact)) continue;  // apart: the hypot below would say so too
			const double distance = between.Norm();
			if (distance >= contact) continue;
			const Vec2 normal = distance > 1e-9 ? between * (1.0 / distance) : Vec2{1, 0};
			const Vec2 half = normal * (0.5 * (contact - distance));
			a.pose.x -= half.x;
			a.pose.y -= half.y;
			b.pose.x += half.x;
			b.pose.y += half.y;
			// who walks into whom: the pusher may be penalised, the pushed one may fall
			const bool a_pushes = a.Upright() && a.FieldVelocity().Dot(normal) > 0.05;
			const bool b_pushes = b.Upright() && b.FieldVelocity().Dot(normal * -1.0) > 0.05;
			if (a_pushes) pushing[i] = true;
			if (b_pushes) pushing[j] = true;
			for (Body* pushed : {a_pushes ? &b : nullptr, b_pushes ? &a : nullptr}) {
				if (pushed && pushed->Upright() && random_.Chance(0.15 * dt)) {
					pushed->motion = Motion::Fallen;
					pushed->motion_time = 0;
					pushed->velocity = {};
					pushed->turn_rate = 0;
					events_.push_back({PhysicsEvent::Type::Fall, static_cast<int>(pushed - bodies.data()), "pushed", 0});
				}
			}
		}
	}
	for (std::size_t i = 0; i < bodies.size(); ++i) {
		bodies[i].pushing_time = pushing[i] ? bodies[i].pushing_time + dt : 0;
		if (!bodies[i].on_field) continue;
		// goal posts stop robots as they stop the ball
		for (const Vec2 post : {Vec2{field::kPostX, field::kPostY}, Vec2{field::kPostX, -field::kPostY},
		                        Vec2{-field::kPostX, field::kPostY}, Vec2{-field::kPostX, -field::kPostY}}) {
			const Vec2 away = bodies[i].pose.Position() - post;
			const double contact = nao::kBodyRadius + field::kPostRadius;
			if (SurelyLonger(away, contact)) continue;
			const double distance = away.Norm();
			if (distance < contact && distance > 1e-9) {
				const Vec2 moved = post + away * (contact / distance);
				bodies[i].pose.x = moved.x;
				bodies[i].pose.y = moved.y;
			}
		}
	}
}

void World::CollideBallWithGoals() {
	for (int side : {1, -1}) {
		for (int post : {1, -1}) {
			if (Bounce(ball, {side * field::kPostX, post * field::kPostY}, field::kPostRadius, kBallRestitutionPost, {})) {
				events_.push_back({PhysicsEvent::Type::Post, -1, "", 0});
			}
		}
		const double back = side * (field::kPostX + field::kGoalDepth);
		const Segment nets[] = {
			{{back, -field::kPostY}, {back, field::kPostY}, 0.0, kBallRestitutionNet},
			{{side * field::kPostX, field::kPostY}, {back, field::kPostY}, 0.0, kBallRestitutionNet},
			{{side * field::kPostX, -field::kPostY}, {back, -field::kPostY}, 0.0, kBallRestitutionNet},
		};
		for (const auto& net : nets) {
			Bounce(ball, ClosestOnSegment(net.a, net.b, ball.position), net.radius, net.restitution, {});
		}
	}
}

}  // namespace kse::sim
