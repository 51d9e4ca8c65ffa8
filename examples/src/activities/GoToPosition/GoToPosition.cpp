// Walk to the position the game asks for (PositionMessage), facing the wanted way.
#include "GoToPosition.h"

#include <common/RobotIO.h>
#include <statechart_engine/Factories.h>

namespace {
const statechart_engine::ActivityRegistrar<GoToPosition> registrar("GoToPosition");
}

void GoToPosition::UserInit() { _io.Bind(*_blk); }

int GoToPosition::Execute() {
	const auto world = _io.Read();
	if (world.position) {
		_io.WalkToFieldPose(world, world.position->posx(), world.position->posy(), world.position->theta());
	} else {
		_io.Stop();
	}
	return 0;
}
