package org.kse.ui.messages;

import java.io.IOException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Optional;
import java.util.SequencedMap;
import java.util.stream.Stream;

import org.kse.messages.LineStarts;
import org.kse.messages.EnumType;
import org.kse.messages.Field;
import org.kse.messages.MessageCatalog;
import org.kse.messages.MessageType;
import org.kse.messages.ProtoFile;
import org.kse.messages.ProtoProblem;
import org.kse.messages.ProtoReader;
import org.kse.messages.ProtoType;
import org.kse.messages.StandardMessages;

/**
 * An editor's text read and linked with the {@code .proto} files around it: the {@code .proto}
 * files of its folder tree as protoc sees them with that folder on its import path (the editor's
 * text for this file, the disk for the others) and the standard messages, combined as
 * {@link StandardMessages#merge(SequencedMap)} does for {@code kse validate}. A standard file
 * (opened read-only) is linked with the other standard files alone.
 */
final class LinkedProto {

	/** Where a message or enum is declared: a file on disk, or a standard file by name. */
	record Declaration(ProtoType type, Path location, String standardName) {
	}

	/** This file as parsed from the editor's text, its field types resolved by the catalog. */
	private final ProtoFile file;
	private final Path location;
	private final StandardMessages.Merged merged;
	private final Positions positions;

	private LinkedProto(ProtoFile file, Path location, StandardMessages.Merged merged, String text) {
		this.file = file;
		this.location = location;
		this.merged = merged;
		this.positions = new Positions(text);
	}

	/** The text of the file at {@code location} (a path on disk) linked with its folder's files. */
	static LinkedProto of(Path location, String text) {
		Path self = location.toAbsolutePath().normalize();
		Path folder = self.getParent();
		SequencedMap<Path, ProtoFile> files = new LinkedHashMap<>();
		ProtoFile[] edited = new ProtoFile[1];
		try (Stream<Path> walk = Files.walk(folder)) {
			for (Path other : walk.filter(p -> p.toString().endsWith(".proto") && Files.isRegularFile(p)).sorted().toList()) {
				if (other.equals(self)) {
					edited[0] = ProtoReader.read(folder.relativize(self), text);
					files.put(self, edited[0]);
				} else {
					files.put(other, ProtoReader.read(folder.relativize(other), read(other)));
				}
			}
		} catch (IOException | RuntimeException e) {
			// An unreadable folder still leaves this file's own problems to show.
		}
		if (edited[0] == null) {
			// not on disk (deleted while open): still this file's problems, linked with what is there
			edited[0] = ProtoReader.read(folder.relativize(self), text);
			files.put(self, edited[0]);
		}
		return new LinkedProto(edited[0], self, StandardMessages.merge(files), text);
	}

	/** A standard file as bundled, linked with the other standard files. */
	static LinkedProto standard(String name) {
		MessageCatalog catalog = StandardMessages.catalog();
		Path path = Path.of(StandardMessages.FOLDER + name);
		ProtoFile file = catalog.files().stream().filter(f -> path.equals(f.file())).findFirst()
				.orElseThrow(() -> new IllegalArgumentException("not a standard message file: " + name));
		return new LinkedProto(file, null, null, StandardMessages.text(name));
	}

	/**
	 * Another file's text, as protoc would read it: UTF-8; a byte that is not is replaced, so a
	 * broken neighbour still lends the types it declares (its own editor says what is wrong).
	 */
	private static String read(Path file) throws IOException {
		return StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPLACE)
				.onUnmappableCharacter(CodingErrorAction.REPLACE).decode(java.nio.ByteBuffer.wrap(Files.readAllBytes(file)))
				.toString();
	}

	ProtoFile file() {
		return file;
	}

	Positions positions() {
		return positions;
	}

	/** What is wrong in this file, its own problems and those linking found (never another file's). */
	List<ProtoProblem> problems() {
		if (merged == null) {
			return List.of();
		}
		return merged.problems().stream().filter(problem -> location.equals(problem.file())).toList();
	}

	/** Notes for this file's types that take the place of standard ones of the same name. */
	List<ProtoProblem> replacements() {
		List<ProtoProblem> notes = new ArrayList<>();
		if (merged == null) {
			return notes;
		}
		for (StandardMessages.Replacement replacement : merged.replacements()) {
			if (!location.equals(replacement.file())) {
				continue;
			}
			Stream.concat(file.messages().stream(), file.enums().stream()).filter(type -> type.fullName().equals(replacement.type()))
					.findFirst()
					.ifPresent(type -> notes.add(new ProtoProblem(location, type.line(), type.column(), type.name()
							+ " replaces the standard " + (type instanceof EnumType ? "enum" : "message") + " of "
							+ replacement.standardFile().toString().replace('\\', '/')
							+ " in this folder's catalog (kse validate and kse generate use this one)")));
		}
		return notes;
	}

	/** The field whose type name covers this offset, or empty. */
	Optional<Field> fieldWithTypeAt(int offset) {
		Deque<MessageType> todo = new ArrayDeque<>(file.messages());
		while (!todo.isEmpty()) {
			MessageType message = todo.pop();
			todo.addAll(message.nestedMessages());
			for (Field field : message.fields()) {
				int start = positions.offset(field.typeLine(), field.typeColumn());
				if (offset >= start && offset <= positions.qualifiedNameEnd(start)) {
					return Optional.of(field);
				}
			}
		}
		return Optional.empty();
	}

	/** Where the type of a field is declared; empty for a scalar or a type no file declares. */
	Optional<Declaration> declarationOf(Field field) {
		Optional<ProtoType> type = field.messageType().<ProtoType>map(m -> m).or(() -> field.enumType());
		return type.map(this::declaration);
	}

	private Declaration declaration(ProtoType type) {
		if (StandardMessages.isStandard(type.file())) {
			return new Declaration(type, null, type.file().getFileName().toString());
		}
		Path path = merged == null ? null : merged.userFiles().get(type.file());
		return new Declaration(type, path, null);
	}

	/**
	 * Offsets of lines and columns as the reader counts them: 1-based, {@code \r\n}, {@code \n}
	 * and a lone {@code \r} each end a line, a column is a UTF-16 char (a tab is one).
	 */
	static final class Positions {
		private final String text;
		private final int[] lineStarts;

		Positions(String text) {
			this.text = text;
			lineStarts = LineStarts.of(text);
		}

		int offset(int line, int column) {
			int start = lineStarts[Math.min(Math.max(line, 1), lineStarts.length) - 1];
			return Math.min(text.length(), start + Math.max(column, 1) - 1);
		}

		/** The end of a name or dotted name ({@code .pkg.Outer.Inner}) starting at {@code start}. */
		int qualifiedNameEnd(int start) {
			int end = start;
			while (end < text.length() && (ProtoScanner.isNamePart(text.charAt(end)) || text.charAt(end) == '.')) {
				end++;
			}
			return end;
		}

		/**
		 * What a squiggle under a problem at {@code offset} covers, {@code [start, end)}: the name,
		 * number or string that starts there, else the one character. A problem placed at the end
		 * of a line or before a blank (where a missing {@code ;} belongs) underlines the token just
		 * before it, which a reader can see.
		 */
		int[] problemRange(int offset) {
			int start = Math.min(offset, text.length());
			if ((start == text.length() || Character.isWhitespace(text.charAt(start))) && start > 0
					&& !Character.isWhitespace(text.charAt(start - 1))) {
				int end = start;
				while (start > 0 && (ProtoScanner.isNamePart(text.charAt(start - 1)) || text.charAt(start - 1) == '.')) {
					start--;
				}
				return new int[] { start == end ? end - 1 : start, end };
			}
			if (start == text.length()) {
				return new int[] { start, start };
			}
			char c = text.charAt(start);
			if (c == '"' || c == '\'') {
				int end = start + 1;
				while (end < text.length() && text.charAt(end) != c && text.charAt(end) != '\n' && text.charAt(end) != '\r') {
					end += text.charAt(end) == '\\' ? 2 : 1;
				}
				return new int[] { start, Math.min(text.length(), end + 1) };
			}
			int end = qualifiedNameEnd(start);
			return new int[] { start, end > start ? end : start + 1 };
		}
	}
}
