/*
 * Hand-written; created once from the Xtext template.
 */
package org.kse.proto.ide;


/**
 * Use this class to register ide components.
 */
public class ProtoIdeModule extends AbstractProtoIdeModule {
}
