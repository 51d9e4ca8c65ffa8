#pragma once

#include <string>

#include <common/RobotIO.h>
#include <statechart_engine/Interfaces.h>

/** The activity NoPlay of the example behaviours (see NoPlay.cpp). */
class NoPlay : public statechart_engine::IActivity {
public:
	void UserInit() override;
	int Execute() override;
	std::string GetName() override { return "NoPlay"; }

private:
	examples::RobotIO _io;
};
