package org.kse.diagram.server.websocket;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.apache.logging.log4j.LogManager;
import org.apache.logging.log4j.Logger;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * The matches that announced themselves in the discovery folder ({@code kse-match --monitor}
 * writes {@code <pid>.json} there for as long as it runs; docs/monitor.md, ADR 0035): what a
 * picker lists and where the relay finds a match's port and key, so that a page never holds the key.
 * <p>
 * A file whose process is gone (a match killed with SIGKILL cannot remove it) or whose pid now
 * belongs to a process started after the match is stale: it is not listed, and it is deleted.
 */
public final class RunningMatches {

	/** Overrides the folder (tests, or a user who wants another one); otherwise the one kse-match uses. */
	public static final String FOLDER_PROPERTY = "kse.monitor.matches";

	/** The largest announcement read: a match of two teams of seven is under 2 KiB. */
	private static final long MAX_FILE_BYTES = 64 * 1024;
	private static final Pattern NAME = Pattern.compile("([1-9][0-9]{0,9})\\.json");
	/** A process started this long after the match announced itself is another process with a reused pid. */
	private static final Duration PID_REUSE_SLACK = Duration.ofSeconds(5);
	private static final Logger LOG = LogManager.getLogger("org.kse.diagram");

	private RunningMatches() {
	}

	/** A robot of a running match. */
	public record Robot(String id, String team, int number, String behaviour) {
	}

	/** A running match: its process, its monitor's port and key, and its robots. */
	public record Match(long pid, int port, String key, long seed, Instant started, List<Robot> robots) {

		/** The robot with this id, if it plays. */
		public Optional<Robot> robot(String id) {
			return robots.stream().filter(robot -> robot.id().equals(id)).findFirst();
		}

		/** What a page may know of it: everything but the port and the key. */
		public JsonObject toPublicJson() {
			JsonObject json = new JsonObject();
			json.addProperty("pid", pid);
			json.addProperty("seed", seed);
			json.addProperty("started", started.toEpochMilli());
			JsonArray list = new JsonArray();
			for (Robot robot : robots) {
				JsonObject entry = new JsonObject();
				entry.addProperty("id", robot.id());
				entry.addProperty("team", robot.team());
				entry.addProperty("number", robot.number());
				entry.addProperty("behaviour", robot.behaviour());
				list.add(entry);
			}
			json.add("robots", list);
			return json;
		}
	}

	/** Where kse-match announces itself: $XDG_RUNTIME_DIR/kse/matches, else ~/.cache/kse/matches (as MatchDiscovery.cpp). */
	public static Path folder() {
		String override = System.getProperty(FOLDER_PROPERTY);
		if (override != null && !override.isEmpty()) {
			return Path.of(override);
		}
		String runtime = System.getenv("XDG_RUNTIME_DIR");
		if (runtime != null && runtime.startsWith("/")) {
			return Path.of(runtime, "kse", "matches");
		}
		String home = System.getenv("HOME");
		return Path.of(home != null && home.startsWith("/") ? home : System.getProperty("user.home"), ".cache", "kse", "matches");
	}

	/** The running matches announced in {@link #folder()}, the newest first. */
	public static List<Match> list() {
		return list(folder());
	}

	/** The running matches announced in {@code folder}, the newest first; stale files are deleted. */
	public static List<Match> list(Path folder) {
		List<Match> matches = new ArrayList<>();
		if (!Files.isDirectory(folder, LinkOption.NOFOLLOW_LINKS)) {
			return matches;
		}
		try (DirectoryStream<Path> files = Files.newDirectoryStream(folder)) {
			for (Path file : files) {
				Matcher name = NAME.matcher(file.getFileName().toString());
				if (name.matches()) {
					read(file, Long.parseLong(name.group(1))).ifPresent(matches::add);
				}
			}
		} catch (IOException unreadable) {
			LOG.warn("cannot list the running matches in " + folder + ": " + unreadable.getMessage());
		}
		matches.sort(Comparator.comparing(Match::started).reversed().thenComparing(Match::pid));
		return matches;
	}

	/** The running match of process {@code pid} announced in {@code folder}. */
	public static Optional<Match> find(Path folder, long pid) {
		if (pid <= 0) {
			return Optional.empty();
		}
		Path file = folder.resolve(pid + ".json");
		return Files.exists(file, LinkOption.NOFOLLOW_LINKS) ? read(file, pid) : Optional.empty();
	}

	private static Optional<Match> read(Path file, long pid) {
		try {
			BasicFileAttributes attributes = Files.readAttributes(file, BasicFileAttributes.class, LinkOption.NOFOLLOW_LINKS);
			if (!attributes.isRegularFile() || attributes.size() > MAX_FILE_BYTES) {
				LOG.warn("ignored " + file + ": not a match's announcement (a link, not a file, or over 64 KiB)");
				return Optional.empty();
			}
			Match match = parse(Files.readString(file, StandardCharsets.UTF_8), pid);
			if (match == null) {
				LOG.warn("ignored " + file + ": not a match's announcement (docs/monitor.md, Picking a match)");
				return Optional.empty();
			}
			if (!alive(match)) {
				// killed without a chance to remove it (SIGKILL, a power cut): whoever reads it first tidies up
				Files.deleteIfExists(file);
				LOG.info("removed the announcement of match " + pid + ", which no longer runs");
				return Optional.empty();
			}
			return Optional.of(match);
		} catch (IOException gone) {
			// removed while reading: the match just ended
			return Optional.empty();
		}
	}

	private static boolean alive(Match match) {
		Optional<ProcessHandle> process = ProcessHandle.of(match.pid());
		if (process.isEmpty() || !process.get().isAlive()) {
			return false;
		}
		// a reused pid: the process living now started after the match had announced itself
		Optional<Instant> start = process.get().info().startInstant();
		return start.isEmpty() || !start.get().isAfter(match.started().plus(PID_REUSE_SLACK));
	}

	/** The announcement's match, or null when it is not one (or names another pid than its file). */
	static Match parse(String text, long pid) {
		try {
			if (!(JsonParser.parseString(text) instanceof JsonObject json) || json.get("pid") == null || json.get("pid").getAsLong() != pid) {
				return null;
			}
			int port = json.get("port").getAsInt();
			String key = json.get("token").getAsString();
			if (port < 1 || port > 65535 || key.isEmpty() || key.length() > 256) {
				return null;
			}
			List<Robot> robots = new ArrayList<>();
			for (JsonElement team : json.getAsJsonArray("teams")) {
				String name = team.getAsJsonObject().get("name").getAsString();
				for (JsonElement player : team.getAsJsonObject().getAsJsonArray("players")) {
					JsonObject robot = player.getAsJsonObject();
					robots.add(new Robot(robot.get("id").getAsString(), name, robot.get("number").getAsInt(), robot.get("behaviour").getAsString()));
				}
			}
			long seed = json.has("seed") ? json.get("seed").getAsLong() : 0;
			return new Match(pid, port, key, seed, Instant.ofEpochMilli(json.get("started").getAsLong()), List.copyOf(robots));
		} catch (RuntimeException malformed) {
			return null;
		}
	}
}
