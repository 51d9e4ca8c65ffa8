/*
 * Hand-written; created once from the Xtext template.
 */
package org.kse.proto.scoping;


/**
 * The grammar has no cross-references: a field's type is a name, resolved across files by the
 * message catalog's TypeResolver with protobuf's scoping rules (ADR 0019).
 */
public class ProtoScopeProvider extends AbstractProtoScopeProvider {

}
