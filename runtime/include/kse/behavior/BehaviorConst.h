#ifndef KSE_BEHAVIOR_BEHAVIOR_CONST_H
#define KSE_BEHAVIOR_BEHAVIOR_CONST_H

// Constants that generated transition code uses unqualified, e.g.
// `gsm->player_state() == PLAYER_PLAYING`. They are declared in kse::behavior and brought
// into the global namespace by the using-declarations below.

namespace kse::behavior {

// GameStateMessage::player_state() values (docs/original-kse.md §9).
constexpr int PLAYER_INITIAL = 0;
constexpr int PLAYER_READY = 1;
constexpr int PLAYER_SET = 2;
constexpr int PLAYER_PLAYING = 3;
constexpr int PLAYER_FINISHED = 4;
constexpr int PLAYER_PENALISED = 5;

}  // namespace kse::behavior

using kse::behavior::PLAYER_FINISHED;
using kse::behavior::PLAYER_INITIAL;
using kse::behavior::PLAYER_PENALISED;
using kse::behavior::PLAYER_PLAYING;
using kse::behavior::PLAYER_READY;
using kse::behavior::PLAYER_SET;

#endif
