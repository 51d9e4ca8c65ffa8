#ifndef STATECHART_ENGINE_STATECHART_ENGINE_H
#define STATECHART_ENGINE_STATECHART_ENGINE_H

// Everything generated Monas code needs from the runtime: the engine (namespace
// statechart_engine), messaging (kse::messaging), the standard messages and the behaviour
// helpers (PLAYER_* constants, readyToKick, ballAway, robotInPosition).
#include "kse/behavior/BehaviorConst.h"
#include "kse/behavior/Guards.h"
#include "kse/messages/all.h"
#include "kse/messaging/Messaging.h"
#include "statechart_engine/Factories.h"
#include "statechart_engine/Definition.h"
#include "statechart_engine/Interfaces.h"
#include "statechart_engine/Statechart.h"
#include "statechart_engine/States.h"
#include "statechart_engine/TimeoutAction.h"
#include "statechart_engine/TransitionSegment.h"

#endif
