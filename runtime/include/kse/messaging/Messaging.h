#ifndef KSE_MESSAGING_MESSAGING_H
#define KSE_MESSAGING_MESSAGING_H

// Everything of namespace kse::messaging.
#include "kse/messaging/Blackboard.h"
#include "kse/messaging/Clock.h"
#include "kse/messaging/Kind.h"
#include "kse/messaging/MessageHub.h"
#include "kse/messaging/Recycled.h"

#endif
