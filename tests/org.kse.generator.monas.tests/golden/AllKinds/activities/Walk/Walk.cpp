#include "Walk.h"

#include <statechart_engine/Factories.h>

namespace {
const statechart_engine::ActivityRegistrar<Walk> registrar("Walk");
}

void Walk::UserInit() {
}

int Walk::Execute() {
	// TODO: the behaviour of Walk
	return 0;
}
