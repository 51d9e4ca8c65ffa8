#include "ChaseBall.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <kse/behavior/BehaviorConst.h>
#include <kse/messages/all.h>
#include <statechart_engine/Factories.h>

namespace {
// the name the statechart's BASIC state asks the factory for
const statechart_engine::ActivityRegistrar<ChaseBall> registrar("ChaseBall");

float Clamp(float value) { return std::max(-1.0f, std::min(1.0f, value)); }
}  // namespace

void ChaseBall::UserInit() {
	// once, before the first Execute(): the topics this activity reads
	_blk->Subscribe("worldstate");
}

int ChaseBall::Execute() {
	_blk->ProcessMessages();  // the blackboard is a snapshot: take in what arrived since the last run

	const auto game = _blk->ReadState<GameStateMessage>("worldstate");  // State: the last value
	if (!game || game->player_state() != PLAYER_PLAYING) {
		Walk(0, 0, 0);
		return 0;
	}
	const auto world = _blk->ReadData<WorldInfo>("worldstate");  // Data: the newest entry
	const auto now = _blk->Now();  // the hub's clock: simulated time in kse-match
	if (world && world->balls_size() > 0) {
		const Ball& ball = world->balls(0);  // robot frame: x forward, y left, metres
		const float bearing = std::atan2(ball.relativey(), ball.relativex());
		const float distance = std::hypot(ball.relativex(), ball.relativey());
		Walk(std::min(1.0f, distance) * std::cos(bearing), 0, 1.5f * bearing);
		Head(bearing, 0.4f);
		_lastSeen = now;
	} else if (now - _lastSeen > std::chrono::seconds(2)) {
		Walk(0, 0, 0.6f);  // lost for two seconds: turn and look
		Head(0, 0.4f);
	}
	// otherwise the last walk command stands: the ball may come back into view
	return 0;  // ignored by the engine
}

void ChaseBall::Walk(float forward, float sideways, float turn) {
	MotionWalkMessage walk;
	walk.set_command("setWalkTargetVelocity");
	walk.add_parameter(Clamp(forward));   // each in [-1, 1] of the walk's limits
	walk.add_parameter(Clamp(sideways));
	walk.add_parameter(Clamp(turn));
	walk.add_parameter(1.0f);
	_blk->Publish("motion", kse::messaging::Kind::Signal, walk);
}

void ChaseBall::Head(float yaw, float pitch) {
	MotionHeadMessage head;
	head.set_command("setHead");
	head.add_parameter(yaw);
	head.add_parameter(pitch);
	_blk->Publish("motion", kse::messaging::Kind::Signal, head);
}
