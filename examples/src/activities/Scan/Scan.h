#pragma once

#include <string>

#include <common/RobotIO.h>
#include <statechart_engine/Interfaces.h>

/** The activity Scan of the example behaviours (see Scan.cpp). */
class Scan : public statechart_engine::IActivity {
public:
	void UserInit() override;
	int Execute() override;
	std::string GetName() override { return "Scan"; }

private:
	examples::RobotIO _io;
	int _step = 0;
};
