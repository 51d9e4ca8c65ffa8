#pragma once

#include <string>

#include <common/RobotIO.h>
#include <statechart_engine/Interfaces.h>

/** The activity Init of the example behaviours (see Init.cpp). */
class Init : public statechart_engine::IActivity {
public:
	void UserInit() override;
	int Execute() override;
	std::string GetName() override { return "Init"; }

private:
	examples::RobotIO _io;
};
