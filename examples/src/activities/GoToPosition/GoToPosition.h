#pragma once

#include <string>

#include <common/RobotIO.h>
#include <statechart_engine/Interfaces.h>

/** The activity GoToPosition of the example behaviours (see GoToPosition.cpp). */
class GoToPosition : public statechart_engine::IActivity {
public:
	void UserInit() override;
	int Execute() override;
	std::string GetName() override { return "GoToPosition"; }

private:
	examples::RobotIO _io;
};
