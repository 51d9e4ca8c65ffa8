package org.kse.expression.validation;

import java.util.Set;

import org.eclipse.emf.ecore.EObject;
import org.eclipse.emf.ecore.util.EcoreUtil;
import org.eclipse.xtext.validation.Check;
import org.kse.expression.transitionExpression.Binary;
import org.kse.expression.transitionExpression.Call;
import org.kse.expression.transitionExpression.Constant;
import org.kse.expression.transitionExpression.MessageAccess;
import org.kse.expression.transitionExpression.MemberCall;
import org.kse.expression.transitionExpression.Not;
import org.kse.expression.transitionExpression.Publish;
import org.kse.expression.transitionExpression.TimeoutAction;
import org.kse.expression.transitionExpression.TransitionExpression;
import org.kse.expression.transitionExpression.TransitionExpressionPackage.Literals;

/**
 * Rules of docs/original-kse.md §6 that the grammar alone cannot state. Each one is reported at the
 * position of the offending word inside the expression.
 */
public class TransitionExpressionValidator extends AbstractTransitionExpressionValidator {

	public static final Set<String> KINDS = Set.of("Signal", "State", "Data");
	public static final String TIMEOUT_CHECK = "TimeoutCheck";

	public static final String BAD_KIND = "kse.te.badKind";
	public static final String BAD_TIMEOUT_CHECK = "kse.te.badTimeoutCheck";
	public static final String TIMEOUT_CHECK_NOT_FIRST = "kse.te.timeoutCheckNotFirst";
	public static final String MISSING_SETTER_VALUE = "kse.te.missingSetterValue";
	public static final String BAD_TIMEOUT = "kse.te.badTimeout";

	@Check
	public void checkKind(MessageAccess access) {
		checkKind(access.getKind(), access, Literals.MESSAGE_ACCESS__KIND);
	}

	@Check
	public void checkKind(Publish publish) {
		checkKind(publish.getKind(), publish, Literals.PUBLISH__KIND);
	}

	private void checkKind(String kind, EObject owner, org.eclipse.emf.ecore.EStructuralFeature feature) {
		if (kind != null && !KINDS.contains(kind)) {
			error("'" + kind + "' is not a message kind: use Signal, State or Data", owner, feature, BAD_KIND);
		}
	}

	@Check
	public void checkTimeoutCheck(Call call) {
		if (!TIMEOUT_CHECK.equals(call.getFunction())) {
			return;
		}
		if (call.getArguments().size() != 1 || !(call.getArguments().get(0) instanceof Constant)) {
			error("TimeoutCheck takes one topic name, as in TimeoutCheck(behavior)", call, Literals.CALL__FUNCTION, BAD_TIMEOUT_CHECK);
		}
		if (EcoreUtil.getRootContainer(call) instanceof TransitionExpression expression && expression.getCondition() != null && firstOperand(expression.getCondition()) != call) {
			warning("put TimeoutCheck first in the condition: it must be evaluated before anything else", call,
					Literals.CALL__FUNCTION, TIMEOUT_CHECK_NOT_FIRST);
		}
	}

	@Check
	public void checkPublishSetter(Publish publish) {
		if (publish.getMembers().isEmpty()) {
			return;
		}
		MemberCall setter = publish.getMembers().get(publish.getMembers().size() - 1);
		if (setter.getArgument() == null) {
			error("publish needs a value for its setter, as in " + setter.getName() + "(1)", setter, Literals.MEMBER_CALL__NAME,
					MISSING_SETTER_VALUE);
		}
	}

	@Check
	public void checkTimeout(TimeoutAction action) {
		if (action.getMilliseconds() <= 0) {
			error("a timeout needs a positive number of milliseconds", action, Literals.TIMEOUT_ACTION__MILLISECONDS, BAD_TIMEOUT);
		}
	}

	private static EObject firstOperand(EObject condition) {
		EObject current = condition;
		while (current instanceof Binary || current instanceof Not) {
			current = current instanceof Binary binary ? binary.getLeft() : ((Not) current).getOperand();
		}
		return current;
	}
}
