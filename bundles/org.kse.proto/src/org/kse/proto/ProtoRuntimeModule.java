/*
 * Hand-written; created once from the Xtext template.
 */
package org.kse.proto;

import org.eclipse.xtext.parser.antlr.ISyntaxErrorMessageProvider;
import org.kse.proto.validation.ProtoSyntaxErrorMessageProvider;

/**
 * Use this class to register components to be used at runtime / without the Equinox extension registry.
 */
public class ProtoRuntimeModule extends AbstractProtoRuntimeModule {

	/** Syntax errors say what the file lacks at that point, in protobuf's words, not which token the parser wanted. */
	public Class<? extends ISyntaxErrorMessageProvider> bindISyntaxErrorMessageProvider() {
		return ProtoSyntaxErrorMessageProvider.class;
	}
}
