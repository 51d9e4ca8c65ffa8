package org.kse.messages;

import java.nio.file.Path;
import java.util.List;

/**
 * One parsed {@code .proto} file. Field types that name messages or enums stay
 * {@link FieldType.Unresolved} until the file is loaded into a {@link MessageCatalog}.
 *
 * @param syntax      "proto2" or "proto3"; "proto2" when the file has no syntax statement, as for protoc
 * @param packageName the package, or "" when there is none (the original Monas messages have none)
 * @param messages    top-level messages, in file order
 * @param enums       top-level enums, in file order
 * @param problems    syntax problems, in file order
 */
public record ProtoFile(Path file, String syntax, String packageName, List<ProtoImport> imports,
		List<MessageType> messages, List<EnumType> enums, List<ProtoProblem> problems) {

	public ProtoFile {
		imports = List.copyOf(imports);
		messages = List.copyOf(messages);
		enums = List.copyOf(enums);
		problems = List.copyOf(problems);
	}
}
