// Walk so that the ball ends at the kicking spot in front of a foot (x 0.122 m,
// y ±0.03 m: readyToKick), facing the opponent goal on the way when localised. A goalkeeper
// that a shot comes at, too close to walk into its way, dives for it instead.
#include "ApproachBall.h"

#include <cmath>

#include <common/RobotIO.h>
#include <statechart_engine/Factories.h>

namespace {
const statechart_engine::ActivityRegistrar<ApproachBall> registrar("ApproachBall");
constexpr float kKickX = 0.122f;
constexpr float kKickY = 0.03f;
}  // namespace

void ApproachBall::UserInit() { _io.Bind(*_blk); }

int ApproachBall::Execute() {
	const auto world = _io.Read();
	if (!world.BallSeen()) {
		_io.Stop();
		return 0;
	}
	if (examples::IsGoalkeeper(world)) {
		const auto crossing = examples::ShotCrossing(world);
		const int dive = crossing ? examples::DiveSide(*crossing) : 0;
		if (dive != 0) {
			_io.Action(dive > 0 ? "goalieLeft" : "goalieRight");
			return 0;
		}
	}
	const auto& ball = world.TheBall();
	const float side = ball.relativey() >= 0 ? 1.0f : -1.0f;
	const float ex = ball.relativex() - kKickX;
	const float ey = ball.relativey() - side * kKickY;
	const float bearing = world.BallBearing();
	// far, or not in front: turn to the ball (backing off when it is beside or behind, so that
	// turning does not sweep it away); near and in front: line up on the kicking spot and the goal
	const float goal = world.BearingTo(examples::kOpponentGoalX, 0.0f);
	const bool inFront = std::fabs(bearing) < 0.6f;
	const bool near = world.BallDistance() < 0.5f && inFront;
	const float turn = near && world.Localised() ? 0.8f * goal : 1.2f * bearing;
	if (std::fabs(bearing) > 1.2f) {
		_io.Walk(-0.4f, 0.0f, turn);
	} else {
		_io.Walk(2.5f * ex, 3.0f * ey, turn);
	}
	_io.TrackBall(world);
	return 0;
}
