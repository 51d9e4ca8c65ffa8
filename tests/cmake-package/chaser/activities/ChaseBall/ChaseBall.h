#pragma once

#include <string>

#include <kse/messaging/Clock.h>
#include <statechart_engine/Interfaces.h>

/** Walks to the ball and keeps it in view; turns on the spot to look for it when it is lost. */
class ChaseBall : public statechart_engine::IActivity {
public:
	void UserInit() override;
	int Execute() override;
	std::string GetName() override { return "ChaseBall"; }

private:
	void Walk(float forward, float sideways, float turn);
	void Head(float yaw, float pitch);

	// kept from one run to the next: the engine creates the activity once
	kse::messaging::TimePoint _lastSeen{};
};
