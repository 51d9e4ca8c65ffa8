// Look for the ball: follow it with the head when it is seen, otherwise sweep the head
// from side to side and, every other sweep, turn the body to look elsewhere.
#include "Scan.h"

#include <common/RobotIO.h>
#include <statechart_engine/Factories.h>

namespace {
const statechart_engine::ActivityRegistrar<Scan> registrar("Scan");
constexpr float kSweep[] = {0.0f, 0.9f, 1.6f, 0.9f, 0.0f, -0.9f, -1.6f, -0.9f};
constexpr int kSweepSteps = sizeof(kSweep) / sizeof(kSweep[0]);
}  // namespace

void Scan::UserInit() { _io.Bind(*_blk); }

int Scan::Execute() {
	const auto world = _io.Read();
	if (world.BallSeen()) {
		_io.TrackBall(world);
		_io.Walk(0, 0, 0.5f * world.BallBearing());
		return 0;
	}
	const int step = _step++ % (2 * kSweepSteps);
	_io.Head(kSweep[step % kSweepSteps], 0.4f);
	_io.Walk(0, 0, step >= kSweepSteps ? 0.6f : 0.0f);
	return 0;
}
