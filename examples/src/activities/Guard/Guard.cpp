// The defender stands between the ball and its own goal, 1.5 m out from the goal line,
// facing the ball.
#include "Guard.h"

#include <cmath>

#include <common/RobotIO.h>
#include <statechart_engine/Factories.h>

namespace {
const statechart_engine::ActivityRegistrar<Guard> registrar("Guard");
constexpr float kDistanceFromGoal = 1.5f;
}  // namespace

void Guard::UserInit() { _io.Bind(*_blk); }

int Guard::Execute() {
	const auto world = _io.Read();
	_io.TrackBall(world);
	if (!world.Localised()) {
		_io.Stop();
		return 0;
	}
	const auto& me = world.info->myposition();
	float ballX = 0.0f;
	float ballY = 0.0f;
	if (world.BallSeen()) {
		const auto& ball = world.TheBall();
		ballX = me.x() + ball.relativex() * std::cos(me.phi()) - ball.relativey() * std::sin(me.phi());
		ballY = me.y() + ball.relativex() * std::sin(me.phi()) + ball.relativey() * std::cos(me.phi());
	}
	const float dx = ballX - examples::kOwnGoalX;
	const float dy = ballY;
	const float length = std::max(0.1f, std::hypot(dx, dy));
	const float x = examples::kOwnGoalX + kDistanceFromGoal * dx / length;
	const float y = kDistanceFromGoal * dy / length;
	_io.WalkToFieldPose(world, x, y, std::atan2(dy, dx));
	return 0;
}
