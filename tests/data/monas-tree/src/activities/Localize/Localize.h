#pragma once

#include <string>

#include <statechart_engine/Interfaces.h>

/** Turns the head until the robot knows where it stands, then says so with LocalizeDone. */
class Localize : public statechart_engine::IActivity {
public:
	void UserInit() override;
	int Execute() override;
	std::string GetName() override { return "Localize"; }
};
