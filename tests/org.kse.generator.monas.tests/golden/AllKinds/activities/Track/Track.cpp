#include "Track.h"

#include <statechart_engine/Factories.h>

namespace {
const statechart_engine::ActivityRegistrar<Track> registrar("Track");
}

void Track::UserInit() {
}

int Track::Execute() {
	// TODO: the behaviour of Track
	return 0;
}
