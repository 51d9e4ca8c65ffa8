// The goalkeeper's dive to the side Stare announced, then the announcement is cleared.
#include "SpecialAction.h"

#include <common/RobotIO.h>
#include <statechart_engine/Factories.h>

namespace {
const statechart_engine::ActivityRegistrar<SpecialAction> registrar("SpecialAction");
}

void SpecialAction::UserInit() { _io.Bind(*_blk); }

int SpecialAction::Execute() {
	const auto fall = _blk->ReadState<FallMessage>("behavior");
	if (fall && fall->fall() != 0) _io.Action(fall->fall() > 0 ? "goalieLeft" : "goalieRight");
	FallMessage reset;
	reset.set_fall(0);
	_blk->Publish("behavior", kse::messaging::Kind::State, reset);
	return 0;
}
