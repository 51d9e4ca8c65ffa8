#include "Search.h"

#include <statechart_engine/Factories.h>

namespace {
const statechart_engine::ActivityRegistrar<Search> registrar("Search");
}

void Search::UserInit() {
	_blk->Subscribe("behavior");
	_blk->Subscribe("worldstate");
}

int Search::Execute() {
	_blk->ProcessMessages();  // see what was published since the last refresh
	[[maybe_unused]] const auto ball = _blk->ReadState<HeadToBMessage>("behavior");
	[[maybe_unused]] const auto world = _blk->ReadData<WorldInfo>("worldstate");
	// TODO: the behaviour of Search
	return 0;
}
