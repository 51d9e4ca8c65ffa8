// Stand up straight, look ahead: the pose every behaviour starts from.
#include "Init.h"

#include <common/RobotIO.h>
#include <statechart_engine/Factories.h>

namespace {
const statechart_engine::ActivityRegistrar<Init> registrar("Init");
}

void Init::UserInit() { examples::Subscribe(*_blk); }

int Init::Execute() {
	examples::Action(*_blk, "InitPose");
	examples::Head(*_blk, 0.0f, 0.3f);
	return 0;
}
