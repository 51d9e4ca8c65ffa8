// Stand up straight, look ahead: the pose every behaviour starts from.
#include "Init.h"

#include <common/RobotIO.h>
#include <statechart_engine/Factories.h>

namespace {
const statechart_engine::ActivityRegistrar<Init> registrar("Init");
}

void Init::UserInit() { _io.Bind(*_blk); }

int Init::Execute() {
	_io.Action("InitPose");
	_io.Head(0.0f, 0.3f);
	return 0;
}
