#include "Track.h"

#include <statechart_engine/Factories.h>

namespace {
const statechart_engine::ActivityRegistrar<Track> registrar("Track");
}

void Track::UserInit() {
}

int Track::Execute() {
	_blk->ProcessMessages();  // see what was published since the last refresh
	// TODO: the behaviour of Track
	return 0;
}
