#ifndef KSE_MESSAGING_KIND_H
#define KSE_MESSAGING_KIND_H

namespace kse::messaging {

/// How a blackboard keeps a published message (docs/semantics.md):
/// - State: the last value per topic and type;
/// - Signal: a queue per topic and type, each entry consumed by the read that returns it;
/// - Data: a time-stamped history per topic and type (bounded).
enum class Kind { Signal, State, Data };

/// "Signal", "State" or "Data".
const char* ToString(Kind kind) noexcept;

}  // namespace kse::messaging

#endif
