// The goalkeeper watches the ball: stand, track it and, when it comes fast towards the
// goal, predict where it crosses the robot's line and announce the side to dive to
// (FallMessage: 1 left, -1 right), which SpecialAction performs.
#include "Stare.h"

#include <common/RobotIO.h>
#include <statechart_engine/Factories.h>

namespace {
const statechart_engine::ActivityRegistrar<Stare> registrar("Stare");
}  // namespace

void Stare::UserInit() { _io.Bind(*_blk); }

int Stare::Execute() {
	const auto world = _io.Read();
	_io.Stop();
	_io.TrackBall(world);
	if (!world.BallSeen()) return 0;
	FallMessage fall;
	const auto crossing = examples::ShotCrossing(world);
	fall.set_fall(crossing ? examples::DiveSide(*crossing) : 0);
	_blk->Publish("behavior", kse::messaging::Kind::State, fall);
	return 0;
}
