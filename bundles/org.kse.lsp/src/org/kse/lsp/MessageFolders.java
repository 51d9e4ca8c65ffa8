package org.kse.lsp;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import org.kse.messages.MessageCatalog;
import org.kse.messages.StandardMessages;

/**
 * The catalog of the standard messages merged with a folder's {@code .proto} files, read again
 * only when one of those files changes (is added, removed, written).
 */
final class MessageFolders {

	private record Read(List<String> files, MessageCatalog catalog) {
	}

	private final Map<Path, Read> read = new HashMap<>();

	synchronized MessageCatalog of(Path folder) {
		List<String> files = stamps(folder);
		Read known = read.get(folder);
		if (known == null || !known.files().equals(files)) {
			known = new Read(files, StandardMessages.catalog(List.of(folder)));
			read.put(folder, known);
		}
		return known.catalog();
	}

	/** Each .proto file under the folder with its size and time of change. */
	private static List<String> stamps(Path folder) {
		try (Stream<Path> paths = Files.walk(folder)) {
			return paths.filter(path -> path.toString().endsWith(".proto")).sorted().map(path -> {
				try {
					return path + " " + Files.size(path) + " " + Files.getLastModifiedTime(path).toMillis();
				} catch (IOException e) {
					return path + " unreadable";
				}
			}).toList();
		} catch (IOException e) {
			throw new UncheckedIOException(folder + ": cannot list the messages folder: " + e.getMessage(), e);
		}
	}
}
