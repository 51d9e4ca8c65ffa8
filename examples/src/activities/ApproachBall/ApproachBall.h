#pragma once

#include <string>

#include <common/RobotIO.h>
#include <statechart_engine/Interfaces.h>

/** The activity ApproachBall of the example behaviours (see ApproachBall.cpp). */
class ApproachBall : public statechart_engine::IActivity {
public:
	void UserInit() override;
	int Execute() override;
	std::string GetName() override { return "ApproachBall"; }

private:
	examples::RobotIO _io;
};
