/*
 * Hand-written; created once from the Xtext template.
 */
package org.kse.proto.validation;


/**
 * Deliberately empty: the rules protoc adds to the grammar (field numbers, labels, duplicates, map
 * keys, names of types across files) are checked where the message catalog is built from this AST,
 * {@code org.kse.messages.ProtoReader} and {@code TypeResolver}, once for every user of the
 * catalog (ADR 0019). A {@code .proto} editor can report them by calling that reader.
 */
public class ProtoValidator extends AbstractProtoValidator {
}
