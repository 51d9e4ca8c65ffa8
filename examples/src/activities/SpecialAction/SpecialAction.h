#pragma once

#include <string>

#include <common/RobotIO.h>
#include <statechart_engine/Interfaces.h>

/** The activity SpecialAction of the example behaviours (see SpecialAction.cpp). */
class SpecialAction : public statechart_engine::IActivity {
public:
	void UserInit() override;
	int Execute() override;
	std::string GetName() override { return "SpecialAction"; }

private:
	examples::RobotIO _io;
};
