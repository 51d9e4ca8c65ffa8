#pragma once

#include <string>

#include <common/RobotIO.h>
#include <statechart_engine/Interfaces.h>

/** The activity Kick of the example behaviours (see Kick.cpp). */
class Kick : public statechart_engine::IActivity {
public:
	void UserInit() override;
	int Execute() override;
	std::string GetName() override { return "Kick"; }

private:
	examples::RobotIO _io;
};
