package org.kse.messages;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Optional;

/**
 * The standard message files as the build parsed them (ADR 0030): {@link ProtoReader}'s result for
 * each of {@link StandardMessages#FILES}, written into this bundle as
 * {@code org/kse/messages/standard/catalog.bin} by {@link #main(String[])} during the Maven build
 * (phase process-classes), and read back at run time instead of parsing. Parsing needs the
 * {@code .proto} language's Xtext injector, about a quarter of a second in every fresh JVM that
 * validates or generates; reading this data needs nothing but {@code java.io}.
 * <p>
 * The data carries the texts it was made from, and is used only when they equal the bundled
 * {@code .proto} files byte for byte: a stale or missing file (a workspace built without Maven,
 * say) makes {@link StandardMessages} parse as before, never answer from old definitions.
 * <p>
 * The objects come out as {@link ProtoReader} makes them: unlinked, field types not yet resolved;
 * {@link MessageCatalog} links them as it does parsed files.
 */
public final class PrecomputedCatalog {

	/** Beside the standard {@code .proto} files, relative to this class. */
	static final String RESOURCE = "standard/catalog.bin";

	/** "KSEM" and a format version, so that a jar of another KSE never feeds this reader. */
	private static final int MAGIC = 0x4b53454d;
	private static final int VERSION = 1;

	private PrecomputedCatalog() {
	}

	/**
	 * The build step: parses the standard files (from the class path, as {@link StandardMessages}
	 * bundles them) and writes their data to the file named by the one argument.
	 */
	public static void main(String[] args) throws IOException {
		if (args.length != 1) {
			throw new IllegalArgumentException("usage: PrecomputedCatalog <output catalog.bin>");
		}
		List<String> texts = StandardMessages.FILES.stream().map(StandardMessages::text).toList();
		List<ProtoFile> parsed = StandardMessages.parseStandard();
		for (ProtoFile file : parsed) {
			if (!file.problems().isEmpty()) {
				// a broken standard file must fail the build, not ship as data
				throw new IllegalStateException("the standard message file has problems: " + file.problems());
			}
		}
		Path output = Path.of(args[0]);
		Files.createDirectories(output.toAbsolutePath().getParent());
		Files.write(output, encode(parsed, texts));
	}

	/**
	 * The bundled data for the bundled standard files, in {@link StandardMessages#FILES} order;
	 * empty when there is none or it was made from other texts.
	 */
	public static Optional<List<ProtoFile>> bundled() {
		byte[] data;
		try (InputStream in = PrecomputedCatalog.class.getResourceAsStream(RESOURCE)) {
			if (in == null) {
				return Optional.empty();
			}
			data = in.readAllBytes();
		} catch (IOException e) {
			return Optional.empty();
		}
		List<String> texts = StandardMessages.FILES.stream().map(StandardMessages::text).toList();
		return decode(data, texts);
	}

	/**
	 * The data of some parsed files, each with the text it was parsed from (same order, same
	 * count). Only what {@link ProtoReader} fills in is kept: names, numbers, labels, type names,
	 * positions, imports and problems.
	 */
	public static byte[] encode(List<ProtoFile> files, List<String> texts) {
		if (files.size() != texts.size()) {
			throw new IllegalArgumentException(files.size() + " files but " + texts.size() + " texts");
		}
		ByteArrayOutputStream bytes = new ByteArrayOutputStream();
		try (DataOutputStream out = new DataOutputStream(bytes)) {
			out.writeInt(MAGIC);
			out.writeInt(VERSION);
			out.writeInt(files.size());
			for (int i = 0; i < files.size(); i++) {
				writeString(out, texts.get(i));
				writeFile(out, files.get(i));
			}
		} catch (IOException e) {
			throw new UncheckedIOException(e); // a byte array never fails to take bytes
		}
		return bytes.toByteArray();
	}

	/**
	 * The files of {@link #encode}'s data, fresh objects on every call (a catalog links them in
	 * place); empty when the data is not of this format or was made from texts other than
	 * {@code texts}.
	 */
	public static Optional<List<ProtoFile>> decode(byte[] data, List<String> texts) {
		try (DataInputStream in = new DataInputStream(new ByteArrayInputStream(data))) {
			if (in.readInt() != MAGIC || in.readInt() != VERSION || in.readInt() != texts.size()) {
				return Optional.empty();
			}
			List<ProtoFile> files = new ArrayList<>();
			for (String text : texts) {
				if (!readString(in).equals(text)) {
					return Optional.empty();
				}
				files.add(readFile(in));
			}
			return in.read() == -1 ? Optional.of(List.copyOf(files)) : Optional.empty();
		} catch (IOException | RuntimeException e) {
			// truncated or garbled: the caller parses instead
			return Optional.empty();
		}
	}

	// ---- writing

	private static void writeFile(DataOutputStream out, ProtoFile file) throws IOException {
		writeNullable(out, file.file() == null ? null : slashed(file.file()));
		writeString(out, file.syntax());
		writeString(out, file.packageName());
		out.writeInt(file.imports().size());
		for (ProtoImport imp : file.imports()) {
			writeString(out, imp.path());
			out.writeByte(imp.modifier().ordinal());
			out.writeInt(imp.line());
			out.writeInt(imp.column());
		}
		out.writeInt(file.messages().size());
		for (MessageType message : file.messages()) {
			writeMessage(out, message);
		}
		out.writeInt(file.enums().size());
		for (EnumType type : file.enums()) {
			writeEnum(out, type);
		}
		out.writeInt(file.problems().size());
		for (ProtoProblem problem : file.problems()) {
			writeNullable(out, problem.file() == null ? null : slashed(problem.file()));
			out.writeInt(problem.line());
			out.writeInt(problem.column());
			writeString(out, problem.message());
		}
	}

	private static void writeMessage(DataOutputStream out, MessageType message) throws IOException {
		writeType(out, message);
		out.writeInt(message.fields().size());
		for (Field field : message.fields()) {
			writeString(out, field.name());
			out.writeInt(field.number());
			out.writeByte(field.label().ordinal());
			writeString(out, field.typeName());
			writeNullable(out, field.mapKeyTypeName().orElse(null));
			writeString(out, field.oneof());
			out.writeInt(field.line());
			out.writeInt(field.column());
			out.writeInt(field.typeLine());
			out.writeInt(field.typeColumn());
		}
		out.writeInt(message.nestedMessages().size());
		for (MessageType nested : message.nestedMessages()) {
			writeMessage(out, nested);
		}
		out.writeInt(message.nestedEnums().size());
		for (EnumType nested : message.nestedEnums()) {
			writeEnum(out, nested);
		}
	}

	private static void writeEnum(DataOutputStream out, EnumType type) throws IOException {
		writeType(out, type);
		out.writeInt(type.values().size());
		for (Map.Entry<String, Integer> value : type.values().entrySet()) {
			writeString(out, value.getKey());
			out.writeInt(value.getValue());
		}
	}

	private static void writeType(DataOutputStream out, ProtoType type) throws IOException {
		writeString(out, type.name());
		writeString(out, type.fullName());
		out.writeInt(type.line());
		out.writeInt(type.column());
	}

	/** Any length and any UTF-16, which writeUTF's 64 KB and modified UTF-8 do not promise. */
	private static void writeString(DataOutputStream out, String text) throws IOException {
		byte[] bytes = text.getBytes(StandardCharsets.UTF_8);
		out.writeInt(bytes.length);
		out.write(bytes);
	}

	private static void writeNullable(DataOutputStream out, String text) throws IOException {
		out.writeBoolean(text != null);
		if (text != null) {
			writeString(out, text);
		}
	}

	/** A file's name as written in the data: '/'-separated, as {@link StandardMessages} names them. */
	private static String slashed(Path path) {
		return path.toString().replace(path.getFileSystem().getSeparator(), "/");
	}

	// ---- reading

	private static ProtoFile readFile(DataInputStream in) throws IOException {
		String name = readNullable(in);
		Path file = name == null ? null : Path.of(name);
		String syntax = readString(in);
		String packageName = readString(in);
		List<ProtoImport> imports = new ArrayList<>();
		for (int i = count(in); i > 0; i--) {
			imports.add(new ProtoImport(readString(in), ProtoImport.Modifier.values()[in.readByte()], in.readInt(), in.readInt()));
		}
		List<MessageType> messages = new ArrayList<>();
		for (int i = count(in); i > 0; i--) {
			messages.add(readMessage(in, file, null));
		}
		List<EnumType> enums = new ArrayList<>();
		for (int i = count(in); i > 0; i--) {
			enums.add(readEnum(in, file, null));
		}
		List<ProtoProblem> problems = new ArrayList<>();
		for (int i = count(in); i > 0; i--) {
			String problemFile = readNullable(in);
			problems.add(new ProtoProblem(problemFile == null ? null : Path.of(problemFile), in.readInt(), in.readInt(), readString(in)));
		}
		return new ProtoFile(file, syntax, packageName, imports, messages, enums, problems);
	}

	private static MessageType readMessage(DataInputStream in, Path file, MessageType parent) throws IOException {
		MessageType message = new MessageType(readString(in), readString(in), file, in.readInt(), in.readInt(), parent);
		for (int i = count(in); i > 0; i--) {
			String name = readString(in);
			int number = in.readInt();
			Field.Label label = Field.Label.values()[in.readByte()];
			String typeName = readString(in);
			String mapKeyTypeName = readNullable(in);
			String oneof = readString(in);
			message.addField(new Field(name, number, label, typeName, mapKeyTypeName, oneof, in.readInt(), in.readInt(),
					in.readInt(), in.readInt()));
		}
		for (int i = count(in); i > 0; i--) {
			message.addMessage(readMessage(in, file, message));
		}
		for (int i = count(in); i > 0; i--) {
			message.addEnum(readEnum(in, file, message));
		}
		return message;
	}

	private static EnumType readEnum(DataInputStream in, Path file, MessageType parent) throws IOException {
		EnumType type = new EnumType(readString(in), readString(in), file, in.readInt(), in.readInt(), parent);
		for (int i = count(in); i > 0; i--) {
			type.addValue(readString(in), in.readInt());
		}
		return type;
	}

	/** A list's length, refused when negative or beyond what the data could still hold. */
	private static int count(DataInputStream in) throws IOException {
		int count = in.readInt();
		if (count < 0 || count > in.available()) {
			throw new IOException("bad count " + count);
		}
		return count;
	}

	private static String readString(DataInputStream in) throws IOException {
		byte[] bytes = new byte[count(in)];
		in.readFully(bytes);
		return new String(bytes, StandardCharsets.UTF_8);
	}

	private static String readNullable(DataInputStream in) throws IOException {
		return in.readBoolean() ? readString(in) : null;
	}
}
