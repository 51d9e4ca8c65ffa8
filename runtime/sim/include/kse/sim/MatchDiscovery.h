#pragma once
// A watched match announces itself (docs/monitor.md, "Picking a match"; ADR 0035): kse-match
// --monitor writes <pid>.json into a per-user folder, so that kse serve and the workbench can
// list the running matches and their robots and connect without the user copying a port and a
// key. The file holds the monitor's key: the folder is the user's only (0700), the file too
// (0600), and it is written whole or not at all (a reader never sees half of it).

#include <cstdint>
#include <string>

namespace kse::sim {

class Match;

/**
 * Where matches announce themselves: $XDG_RUNTIME_DIR/kse/matches (a per-user folder the system
 * empties at logout), else $HOME/.cache/kse/matches; empty when neither variable is set.
 */
std::string DiscoveryFolder();

/** The announcement's content: pid, port, token, started (ms since the epoch) and the match record's fields (seed, teams...). */
std::string AnnouncementJson(const Match& match, long pid, std::uint16_t port, const std::string& token, double started_ms);

/** A match's file in the discovery folder, there from construction until Remove() or destruction. */
class MatchAnnouncement {
public:
	/**
	 * Makes the folder (0700; an existing one of this user is narrowed to 0700, one of another
	 * user refused) and writes {@code folder}/<pid>.json (0600) atomically. Throws
	 * std::runtime_error saying what failed and where.
	 */
	MatchAnnouncement(const std::string& folder, const std::string& json);
	~MatchAnnouncement();
	MatchAnnouncement(const MatchAnnouncement&) = delete;
	MatchAnnouncement& operator=(const MatchAnnouncement&) = delete;

	const std::string& Path() const noexcept { return path_; }
	/** Removes the file (idempotent). */
	void Remove() noexcept;

private:
	std::string path_;
	bool removed_ = false;
};

}  // namespace kse::sim
