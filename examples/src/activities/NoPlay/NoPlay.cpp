// Outside PLAYING: walk to the kick-off position while READY, stand still otherwise.
#include "NoPlay.h"

#include <common/RobotIO.h>
#include <statechart_engine/Factories.h>

namespace {
const statechart_engine::ActivityRegistrar<NoPlay> registrar("NoPlay");
}

void NoPlay::UserInit() { examples::Subscribe(*_blk); }

int NoPlay::Execute() {
	const auto world = examples::World::Read(*_blk);
	if (world.PlayerState() == PLAYER_READY && world.position) {
		examples::WalkToFieldPose(*_blk, world, world.position->posx(), world.position->posy(), world.position->theta());
	} else {
		examples::Stop(*_blk);
	}
	examples::TrackBall(*_blk, world);
	return 0;
}
