// Outside PLAYING: walk to the kick-off position while READY, stand still otherwise.
#include "NoPlay.h"

#include <common/RobotIO.h>
#include <statechart_engine/Factories.h>

namespace {
const statechart_engine::ActivityRegistrar<NoPlay> registrar("NoPlay");
}

void NoPlay::UserInit() { _io.Bind(*_blk); }

int NoPlay::Execute() {
	const auto world = _io.Read();
	if (world.PlayerState() == PLAYER_READY && world.position) {
		_io.WalkToFieldPose(world, world.position->posx(), world.position->posy(), world.position->theta());
	} else {
		_io.Stop();
	}
	_io.TrackBall(world);
	return 0;
}
