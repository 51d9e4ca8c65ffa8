#include "Walk.h"

#include <statechart_engine/Factories.h>

namespace {
const statechart_engine::ActivityRegistrar<Walk> registrar("Walk");
}

void Walk::UserInit() {
}

int Walk::Execute() {
	_blk->ProcessMessages();  // see what was published since the last refresh
	// TODO: the behaviour of Walk
	return 0;
}
