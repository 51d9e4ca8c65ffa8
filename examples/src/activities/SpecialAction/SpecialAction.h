#pragma once

#include <string>

#include <statechart_engine/Interfaces.h>

/** The activity SpecialAction of the example behaviours (see SpecialAction.cpp). */
class SpecialAction : public statechart_engine::IActivity {
public:
	void UserInit() override;
	int Execute() override;
	std::string GetName() override { return "SpecialAction"; }

};
