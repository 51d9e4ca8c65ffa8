// The goalkeeper watches the ball: stand, track it and, when it comes fast towards the
// goal, predict where it crosses the robot's line and announce the side to dive to
// (FallMessage: 1 left, -1 right), which SpecialAction performs.
#include "Stare.h"

#include <cmath>

#include <common/RobotIO.h>
#include <statechart_engine/Factories.h>

namespace {
const statechart_engine::ActivityRegistrar<Stare> registrar("Stare");
constexpr float kShotSpeed = 0.4f;   // m/s towards the robot
constexpr float kReach = 0.7f;       // a dive covers about this far to the side
}  // namespace

void Stare::UserInit() { examples::Subscribe(*_blk); }

int Stare::Execute() {
	const auto world = examples::World::Read(*_blk);
	examples::Stop(*_blk);
	examples::TrackBall(*_blk, world);
	if (!world.BallSeen()) return 0;
	const auto& ball = world.TheBall();
	FallMessage fall;
	fall.set_fall(0);
	if (ball.relativexspeed() < -kShotSpeed && ball.relativex() > 0) {
		const float time = ball.relativex() / -ball.relativexspeed();
		const float crossing = ball.relativey() + ball.relativeyspeed() * time;
		if (std::fabs(crossing) > 0.15f && std::fabs(crossing) < kReach + 0.4f) fall.set_fall(crossing > 0 ? 1 : -1);
	}
	_blk->Publish("behavior", kse::messaging::Kind::State, fall);
	return 0;
}
