// Kick towards the opponent goal: a forward kick with the foot on the ball's side when the
// goal is roughly ahead, a side kick when it is to one side.
#include "Kick.h"

#include <cmath>

#include <common/RobotIO.h>
#include <statechart_engine/Factories.h>

namespace {
const statechart_engine::ActivityRegistrar<Kick> registrar("Kick");
constexpr float kSideKickBearing = 0.9f;  // about 50 degrees
}  // namespace

void Kick::UserInit() { _io.Bind(*_blk); }

int Kick::Execute() {
	const auto world = _io.Read();
	const float goal = world.BearingTo(examples::kOpponentGoalX, 0.0f);
	const bool leftFoot = !world.BallSeen() || world.TheBall().relativey() >= 0;
	if (std::fabs(goal) > kSideKickBearing) {
		_io.Action(goal > 0 ? "KickSideLeft" : "KickSideRight");
	} else {
		_io.Action(leftFoot ? "KickForwardLeft" : "KickForwardRight");
	}
	return 0;
}
