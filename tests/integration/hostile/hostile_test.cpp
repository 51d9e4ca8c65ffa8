// tests/data/hostile/Hostile.stct puts C++ into its labels ("0.2\"); system(\"touch
// kse-injected\"); //", "*/ ... /*") and ends names with a backslash, which would continue a
// line comment over the next line of code. Generated and compiled, the statechart must take its
// three transitions and create no file.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <kse/messaging/Clock.h>
#include <kse/messaging/MessageHub.h>
#include <statechart_engine/Factories.h>
#include <statechart_engine/Statechart.h>

namespace {

TEST(Hostile, LabelsAndNamesNeverBecomeCode) {
	std::filesystem::remove("kse-injected");
	kse::messaging::ManualClock clock;
	kse::messaging::MessageHub hub(clock);
	statechart_engine::Options options;
	options.inline_activities = true;
	auto chart = statechart_engine::StatechartFactory::Instance().Create("Hostile", hub, options);
	ASSERT_NE(chart, nullptr);
	std::vector<std::string> taken;
	chart->Chart().SetObserver([&](const statechart_engine::TransitionSegmentBase& segment) {
		taken.push_back(segment.Source()->Label() + " -> " + segment.Target()->Label());
	});
	chart->Chart().RunUntilStable();
	ASSERT_EQ(taken.size(), 3u) << "a transition after a comment ending in a backslash is still there";
	EXPECT_EQ(taken[0], "0.1 -> 0.2\"); system(\"touch kse-injected\"); //") << "labels are kept as text";
	EXPECT_EQ(taken[2], "0.3 */ int injected = 1; /* -> 0.4\\");
	EXPECT_FALSE(std::filesystem::exists("kse-injected")) << "a label ran a shell command";
}

}  // namespace
