#pragma once

#include <string>

#include <common/RobotIO.h>
#include <statechart_engine/Interfaces.h>

/** The activity Guard of the example behaviours (see Guard.cpp). */
class Guard : public statechart_engine::IActivity {
public:
	void UserInit() override;
	int Execute() override;
	std::string GetName() override { return "Guard"; }

private:
	examples::RobotIO _io;
};
