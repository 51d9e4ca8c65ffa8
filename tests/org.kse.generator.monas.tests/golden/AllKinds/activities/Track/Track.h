#pragma once

#include <string>

#include <kse/messages/all.h>
#include <statechart_engine/Interfaces.h>

/** The activity Track: written by you, never overwritten by KSE. */
class Track : public statechart_engine::IActivity {
public:
	void UserInit() override;
	int Execute() override;
	std::string GetName() override { return "Track"; }
};
