#include "Localize.h"

#include <statechart_engine/Factories.h>

#include "Localization.pb.h"

namespace {
const statechart_engine::ActivityRegistrar<Localize> registrar("Localize");
}

void Localize::UserInit() {
	_blk->Subscribe("behavior");
}

int Localize::Execute() {
	LocalizeDone done;
	done.set_moveon(1);
	_blk->Publish("behavior", kse::messaging::Kind::State, done);
	return 0;
}
