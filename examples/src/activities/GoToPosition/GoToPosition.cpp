// Walk to the position the game asks for (PositionMessage), facing the wanted way.
#include "GoToPosition.h"

#include <common/RobotIO.h>
#include <statechart_engine/Factories.h>

namespace {
const statechart_engine::ActivityRegistrar<GoToPosition> registrar("GoToPosition");
}

void GoToPosition::UserInit() { examples::Subscribe(*_blk); }

int GoToPosition::Execute() {
	const auto world = examples::World::Read(*_blk);
	if (world.position) {
		examples::WalkToFieldPose(*_blk, world, world.position->posx(), world.position->posy(), world.position->theta());
	} else {
		examples::Stop(*_blk);
	}
	return 0;
}
