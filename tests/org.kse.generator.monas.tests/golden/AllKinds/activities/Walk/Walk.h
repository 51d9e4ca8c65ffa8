#pragma once

#include <string>

#include <kse/messages/all.h>
#include <statechart_engine/Interfaces.h>

/** The activity Walk: written by you, never overwritten by KSE. */
class Walk : public statechart_engine::IActivity {
public:
	void UserInit() override;
	int Execute() override;
	std::string GetName() override { return "Walk"; }
};
