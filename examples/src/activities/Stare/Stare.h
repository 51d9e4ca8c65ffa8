#pragma once

#include <string>

#include <common/RobotIO.h>
#include <statechart_engine/Interfaces.h>

/** The activity Stare of the example behaviours (see Stare.cpp). */
class Stare : public statechart_engine::IActivity {
public:
	void UserInit() override;
	int Execute() override;
	std::string GetName() override { return "Stare"; }

private:
	examples::RobotIO _io;
	float _lastDistance = -1.0f;
};
