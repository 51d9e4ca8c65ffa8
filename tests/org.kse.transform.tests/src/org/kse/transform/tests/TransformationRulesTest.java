package org.kse.transform.tests;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Stream;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.kse.model.statechart.Model;

/**
 * Every operator alone and nested, with the expected statechart written by hand from
 * the rules of docs/original-kse.md §3. Expected: the states in document order ("label TYPE name",
 * the name left out when it equals the label), then a line "=>" followed by the
 * transitions by label.
 */
class TransformationRulesTest {

	static Stream<Arguments> formulas() {
		return Stream.of(
				// a lone name becomes a sequence of one (the original crashed)
				Arguments.of("a = B", """
						0 OR a
						0.1 START
						0.2 BASIC B
						0.3 END
						=> 0.1->0.2 0.2->0.3"""),
				Arguments.of("a = B.C", """
						0 OR a
						0.1 START
						0.2 BASIC B
						0.3 BASIC C
						0.4 END
						=> 0.1->0.2 0.2->0.3 0.3->0.4"""),
				Arguments.of("a = B . C . D", """
						0 OR a
						0.1 START
						0.2 BASIC B
						0.3 BASIC C
						0.4 BASIC D
						0.5 END
						=> 0.1->0.2 0.2->0.3 0.3->0.4 0.4->0.5"""),
				Arguments.of("a = B|C", """
						0 OR a
						0.1 START
						0.2 CONDITION
						0.3 BASIC B
						0.4 BASIC C
						0.5 END
						=> 0.1->0.2 0.2->0.3 0.2->0.4 0.3->0.5 0.4->0.5"""),
				Arguments.of("a = B | C | D", """
						0 OR a
						0.1 START
						0.2 CONDITION
						0.3 BASIC B
						0.4 BASIC C
						0.5 BASIC D
						0.6 END
						=> 0.1->0.2 0.2->0.3 0.2->0.4 0.2->0.5 0.3->0.6 0.4->0.6 0.5->0.6"""),
				Arguments.of("a = B||C", """
						0 OR a
						0.1 START
						0.2 AND B_parallel_C
						0.2.1 OR
						0.2.1.1 START
						0.2.1.2 BASIC B
						0.2.1.3 END
						0.2.2 OR
						0.2.2.1 START
						0.2.2.2 BASIC C
						0.2.2.3 END
						0.3 END
						=> 0.1->0.2 0.2->0.3 0.2.1.1->0.2.1.2 0.2.1.2->0.2.1.3 0.2.2.1->0.2.2.2 0.2.2.2->0.2.2.3"""),
				Arguments.of("a = B||C||D", """
						0 OR a
						0.1 START
						0.2 AND B_parallel_C_parallel_D
						0.2.1 OR
						0.2.1.1 START
						0.2.1.2 BASIC B
						0.2.1.3 END
						0.2.2 OR
						0.2.2.1 START
						0.2.2.2 BASIC C
						0.2.2.3 END
						0.2.3 OR
						0.2.3.1 START
						0.2.3.2 BASIC D
						0.2.3.3 END
						0.3 END
						=> 0.1->0.2 0.2->0.3 0.2.1.1->0.2.1.2 0.2.1.2->0.2.1.3 0.2.2.1->0.2.2.2 0.2.2.2->0.2.2.3 0.2.3.1->0.2.3.2 0.2.3.2->0.2.3.3"""),
				// a lone suffixed term shapes the root itself
				Arguments.of("a = B*", """
						0 OR a
						0.1 START
						0.2 CONDITION
						0.3 BASIC B
						0.4 END
						=> 0.1->0.2 0.2->0.3 0.3->0.3 0.2->0.4 0.3->0.4"""),
				Arguments.of("a = B+", """
						0 OR a
						0.1 START
						0.2 BASIC B
						0.3 END
						=> 0.1->0.2 0.2->0.2 0.2->0.3"""),
				Arguments.of("a = B~", """
						0 OR a
						0.1 START
						0.2 BASIC B
						=> 0.1->0.2 0.2->0.2"""),
				Arguments.of("a = [B]", """
						0 OR a
						0.1 START
						0.2 CONDITION
						0.3 BASIC B
						0.4 END
						=> 0.1->0.2 0.2->0.3 0.2->0.4 0.3->0.4"""),
				// a group without suffix is expanded in place (the original crashed)
				Arguments.of("a = (B.C)", """
						0 OR a
						0.1 START
						0.2 BASIC B
						0.3 BASIC C
						0.4 END
						=> 0.1->0.2 0.2->0.3 0.3->0.4"""),
				// a lone |x~|n makes the root itself its AND state, as the original did
				Arguments.of("a = |B~|2", """
						0 AND a
						0.1 OR
						0.1.1 START
						0.1.2 BASIC B
						0.1.3 END
						0.2 OR
						0.2.1 START
						0.2.2 BASIC B
						0.2.3 END
						=> 0.1.1->0.1.2 0.1.2->0.1.3 0.2.1->0.2.2 0.2.2->0.2.3"""),
				// ... and so does a group holding only |x~|n, since a group without suffix is laid out in place
				Arguments.of("a = (|B~|1)", """
						0 AND a
						0.1 OR
						0.1.1 START
						0.1.2 BASIC B
						0.1.3 END
						=> 0.1.1->0.1.2 0.1.2->0.1.3"""),
				// suffixes chain: each applies to the term built by the one before
				Arguments.of("a = B+~", """
						0 OR a
						0.1 START
						0.2 OR B_one_or_more_times_
						0.2.1 START
						0.2.2 BASIC B
						0.2.3 END
						=> 0.1->0.2 0.2->0.2 0.2.1->0.2.2 0.2.2->0.2.2 0.2.2->0.2.3"""),
				Arguments.of("a = |B~|2+", """
						0 OR a
						0.1 START
						0.2 AND _or_B_forever__or_2
						0.2.1 OR
						0.2.1.1 START
						0.2.1.2 BASIC B
						0.2.1.3 END
						0.2.2 OR
						0.2.2.1 START
						0.2.2.2 BASIC B
						0.2.2.3 END
						0.3 END
						=> 0.1->0.2 0.2->0.2 0.2->0.3 0.2.1.1->0.2.1.2 0.2.1.2->0.2.1.3 0.2.2.1->0.2.2.2 0.2.2.2->0.2.2.3"""),
				Arguments.of("a = [B]+~", """
						0 OR a
						0.1 START
						0.2 OR _open_option_B_close_option__one_or_more_times_
						0.2.1 START
						0.2.2 OR _open_option_B_close_option_
						0.2.2.1 START
						0.2.2.2 CONDITION
						0.2.2.3 BASIC B
						0.2.2.4 END
						0.2.3 END
						=> 0.1->0.2 0.2->0.2 0.2.1->0.2.2 0.2.2->0.2.2 0.2.2->0.2.3 0.2.2.1->0.2.2.2 0.2.2.2->0.2.2.3 0.2.2.2->0.2.2.4 0.2.2.3->0.2.2.4"""),
				Arguments.of("a = B*+", """
						0 OR a
						0.1 START
						0.2 OR B_zero_or_more_times_
						0.2.1 START
						0.2.2 CONDITION
						0.2.3 BASIC B
						0.2.4 END
						0.3 END
						=> 0.1->0.2 0.2->0.2 0.2->0.3 0.2.1->0.2.2 0.2.2->0.2.3 0.2.3->0.2.3 0.2.2->0.2.4 0.2.3->0.2.4"""),
				Arguments.of("a = X.(B.C)+~", """
						0 OR a
						0.1 START
						0.2 BASIC X
						0.3 OR _open_group_B_sequence_C_close_group__one_or_more_times__forever_
						0.3.1 START
						0.3.2 OR _open_group_B_sequence_C_close_group__one_or_more_times_
						0.3.2.1 START
						0.3.2.2 OR _open_group_B_sequence_C_close_group_
						0.3.2.2.1 START
						0.3.2.2.2 BASIC B
						0.3.2.2.3 BASIC C
						0.3.2.2.4 END
						0.3.2.3 END
						0.4 END
						=> 0.1->0.2 0.2->0.3 0.3->0.4 0.3.1->0.3.2 0.3.2->0.3.2 0.3.2.1->0.3.2.2 0.3.2.2->0.3.2.2 0.3.2.2->0.3.2.3 \
						0.3.2.2.1->0.3.2.2.2 0.3.2.2.2->0.3.2.2.3 0.3.2.2.3->0.3.2.2.4"""),
				// a name defined again means its last definition, the root's too
				Arguments.of("a = b\nb = C\nb = D|E", """
						0 OR a
						0.1 START
						0.2 OR b
						0.2.1 START
						0.2.2 CONDITION
						0.2.3 BASIC D
						0.2.4 BASIC E
						0.2.5 END
						0.3 END
						=> 0.1->0.2 0.2->0.3 0.2.1->0.2.2 0.2.2->0.2.3 0.2.2->0.2.4 0.2.3->0.2.5 0.2.4->0.2.5"""),
				Arguments.of("a = B\na = C.D", """
						0 OR a
						0.1 START
						0.2 BASIC C
						0.3 BASIC D
						0.4 END
						=> 0.1->0.2 0.2->0.3 0.3->0.4"""),
				Arguments.of("a = B.C+", """
						0 OR a
						0.1 START
						0.2 BASIC B
						0.3 OR C_one_or_more_times_
						0.3.1 START
						0.3.2 BASIC C
						0.3.3 END
						0.4 END
						=> 0.1->0.2 0.2->0.3 0.3->0.4 0.3.1->0.3.2 0.3.2->0.3.2 0.3.2->0.3.3"""),
				Arguments.of("a = B.C*", """
						0 OR a
						0.1 START
						0.2 BASIC B
						0.3 OR C_zero_or_more_times_
						0.3.1 START
						0.3.2 CONDITION
						0.3.3 BASIC C
						0.3.4 END
						0.4 END
						=> 0.1->0.2 0.2->0.3 0.3->0.4 0.3.1->0.3.2 0.3.2->0.3.3 0.3.3->0.3.3 0.3.2->0.3.4 0.3.3->0.3.4"""),
				Arguments.of("a = B.C~", """
						0 OR a
						0.1 START
						0.2 BASIC B
						0.3 OR C_forever_
						0.3.1 START
						0.3.2 BASIC C
						0.4 END
						=> 0.1->0.2 0.2->0.3 0.3->0.4 0.3.1->0.3.2 0.3.2->0.3.2"""),
				Arguments.of("a = B.[C]", """
						0 OR a
						0.1 START
						0.2 BASIC B
						0.3 OR _open_option_C_close_option_
						0.3.1 START
						0.3.2 CONDITION
						0.3.3 BASIC C
						0.3.4 END
						0.4 END
						=> 0.1->0.2 0.2->0.3 0.3->0.4 0.3.1->0.3.2 0.3.2->0.3.3 0.3.2->0.3.4 0.3.3->0.3.4"""),
				Arguments.of("a = B.(C|D)", """
						0 OR a
						0.1 START
						0.2 BASIC B
						0.3 OR _open_group_C_or_D_close_group_
						0.3.1 START
						0.3.2 CONDITION
						0.3.3 BASIC C
						0.3.4 BASIC D
						0.3.5 END
						0.4 END
						=> 0.1->0.2 0.2->0.3 0.3->0.4 0.3.1->0.3.2 0.3.2->0.3.3 0.3.2->0.3.4 0.3.3->0.3.5 0.3.4->0.3.5"""),
				Arguments.of("a = B.|C~|2", """
						0 OR a
						0.1 START
						0.2 BASIC B
						0.3 AND _or_C_forever__or_2
						0.3.1 OR
						0.3.1.1 START
						0.3.1.2 BASIC C
						0.3.1.3 END
						0.3.2 OR
						0.3.2.1 START
						0.3.2.2 BASIC C
						0.3.2.3 END
						0.4 END
						=> 0.1->0.2 0.2->0.3 0.3->0.4 0.3.1.1->0.3.1.2 0.3.1.2->0.3.1.3 0.3.2.1->0.3.2.2 0.3.2.2->0.3.2.3"""),
				Arguments.of("a = B.c\nc = X|Y", """
						0 OR a
						0.1 START
						0.2 BASIC B
						0.3 OR c
						0.3.1 START
						0.3.2 CONDITION
						0.3.3 BASIC X
						0.3.4 BASIC Y
						0.3.5 END
						0.4 END
						=> 0.1->0.2 0.2->0.3 0.3->0.4 0.3.1->0.3.2 0.3.2->0.3.3 0.3.2->0.3.4 0.3.3->0.3.5 0.3.4->0.3.5"""),
				Arguments.of("a = c+\nc = D.E", """
						0 OR a
						0.1 START
						0.2 OR c
						0.2.1 START
						0.2.2 BASIC D
						0.2.3 BASIC E
						0.2.4 END
						0.3 END
						=> 0.1->0.2 0.2->0.2 0.2->0.3 0.2.1->0.2.2 0.2.2->0.2.3 0.2.3->0.2.4"""),
				Arguments.of("a = (B|C)+", """
						0 OR a
						0.1 START
						0.2 OR _open_group_B_or_C_close_group_
						0.2.1 START
						0.2.2 CONDITION
						0.2.3 BASIC B
						0.2.4 BASIC C
						0.2.5 END
						0.3 END
						=> 0.1->0.2 0.2->0.2 0.2->0.3 0.2.1->0.2.2 0.2.2->0.2.3 0.2.2->0.2.4 0.2.3->0.2.5 0.2.4->0.2.5"""),
				Arguments.of("a = [B.C]", """
						0 OR a
						0.1 START
						0.2 CONDITION
						0.3 OR B_sequence_C
						0.3.1 START
						0.3.2 BASIC B
						0.3.3 BASIC C
						0.3.4 END
						0.4 END
						=> 0.1->0.2 0.2->0.3 0.2->0.4 0.3->0.4 0.3.1->0.3.2 0.3.2->0.3.3 0.3.3->0.3.4"""),
				Arguments.of("a = [B+]", """
						0 OR a
						0.1 START
						0.2 CONDITION
						0.3 OR B_one_or_more_times_
						0.3.1 START
						0.3.2 BASIC B
						0.3.3 END
						0.4 END
						=> 0.1->0.2 0.2->0.3 0.2->0.4 0.3->0.4 0.3.1->0.3.2 0.3.2->0.3.2 0.3.2->0.3.3"""),
				Arguments.of("a = (B.C)*", """
						0 OR a
						0.1 START
						0.2 CONDITION
						0.3 OR _open_group_B_sequence_C_close_group_
						0.3.1 START
						0.3.2 BASIC B
						0.3.3 BASIC C
						0.3.4 END
						0.4 END
						=> 0.1->0.2 0.2->0.3 0.3->0.3 0.2->0.4 0.3->0.4 0.3.1->0.3.2 0.3.2->0.3.3 0.3.3->0.3.4"""),
				Arguments.of("a = B.(C||D)", """
						0 OR a
						0.1 START
						0.2 BASIC B
						0.3 OR _open_group_C_parallel_D_close_group_
						0.3.1 START
						0.3.2 AND C_parallel_D
						0.3.2.1 OR
						0.3.2.1.1 START
						0.3.2.1.2 BASIC C
						0.3.2.1.3 END
						0.3.2.2 OR
						0.3.2.2.1 START
						0.3.2.2.2 BASIC D
						0.3.2.2.3 END
						0.3.3 END
						0.4 END
						=> 0.1->0.2 0.2->0.3 0.3->0.4 0.3.1->0.3.2 0.3.2->0.3.3 0.3.2.1.1->0.3.2.1.2 0.3.2.1.2->0.3.2.1.3 0.3.2.2.1->0.3.2.2.2 0.3.2.2.2->0.3.2.2.3"""),
				// an operator nested inside a term of the same operator
				Arguments.of("a = (B.C)+.D", """
						0 OR a
						0.1 START
						0.2 OR _open_group_B_sequence_C_close_group__one_or_more_times_
						0.2.1 START
						0.2.2 OR _open_group_B_sequence_C_close_group_
						0.2.2.1 START
						0.2.2.2 BASIC B
						0.2.2.3 BASIC C
						0.2.2.4 END
						0.2.3 END
						0.3 BASIC D
						0.4 END
						=> 0.1->0.2 0.2->0.3 0.3->0.4 0.2.1->0.2.2 0.2.2->0.2.2 0.2.2->0.2.3 0.2.2.1->0.2.2.2 0.2.2.2->0.2.2.3 0.2.2.3->0.2.2.4"""),
				// the same term twice at one level: two states (the original mixed them up)
				Arguments.of("a = B|C|B", """
						0 OR a
						0.1 START
						0.2 CONDITION
						0.3 BASIC B
						0.4 BASIC C
						0.5 BASIC B
						0.6 END
						=> 0.1->0.2 0.2->0.3 0.2->0.4 0.2->0.5 0.3->0.6 0.4->0.6 0.5->0.6"""),
				// a capability used twice expands twice
				Arguments.of("a = b.b\nb = C|D", """
						0 OR a
						0.1 START
						0.2 OR b
						0.2.1 START
						0.2.2 CONDITION
						0.2.3 BASIC C
						0.2.4 BASIC D
						0.2.5 END
						0.3 OR b
						0.3.1 START
						0.3.2 CONDITION
						0.3.3 BASIC C
						0.3.4 BASIC D
						0.3.5 END
						0.4 END
						=> 0.1->0.2 0.2->0.3 0.3->0.4 0.2.1->0.2.2 0.2.2->0.2.3 0.2.2->0.2.4 0.2.3->0.2.5 0.2.4->0.2.5 0.3.1->0.3.2 0.3.2->0.3.3 0.3.2->0.3.4 0.3.3->0.3.5 0.3.4->0.3.5"""),
				Arguments.of("a = [B|C]", """
						0 OR a
						0.1 START
						0.2 CONDITION
						0.3 OR B_or_C
						0.3.1 START
						0.3.2 CONDITION
						0.3.3 BASIC B
						0.3.4 BASIC C
						0.3.5 END
						0.4 END
						=> 0.1->0.2 0.2->0.3 0.2->0.4 0.3->0.4 0.3.1->0.3.2 0.3.2->0.3.3 0.3.2->0.3.4 0.3.3->0.3.5 0.3.4->0.3.5"""),
				Arguments.of("a = B.|c~|1\nc = D+", """
						0 OR a
						0.1 START
						0.2 BASIC B
						0.3 AND _or_c_forever__or_1
						0.3.1 OR
						0.3.1.1 START
						0.3.1.2 OR c
						0.3.1.2.1 START
						0.3.1.2.2 BASIC D
						0.3.1.2.3 END
						0.3.1.3 END
						0.4 END
						=> 0.1->0.2 0.2->0.3 0.3->0.4 0.3.1.1->0.3.1.2 0.3.1.2->0.3.1.3 0.3.1.2.1->0.3.1.2.2 0.3.1.2.2->0.3.1.2.2 0.3.1.2.2->0.3.1.2.3"""),
				// tabs, blanks, comments and blank lines change nothing
				Arguments.of("// a comment\n\na\t=\tB  .\tC   // done\n\n", """
						0 OR a
						0.1 START
						0.2 BASIC B
						0.3 BASIC C
						0.4 END
						=> 0.1->0.2 0.2->0.3 0.3->0.4"""),
				Arguments.of("a = B.C~.D", """
						0 OR a
						0.1 START
						0.2 BASIC B
						0.3 OR C_forever_
						0.3.1 START
						0.3.2 BASIC C
						0.4 BASIC D
						0.5 END
						=> 0.1->0.2 0.2->0.3 0.3->0.4 0.4->0.5 0.3.1->0.3.2 0.3.2->0.3.2"""),
				Arguments.of("a = ([B]|C*)", """
						0 OR a
						0.1 START
						0.2 CONDITION
						0.3 OR _open_option_B_close_option_
						0.3.1 START
						0.3.2 CONDITION
						0.3.3 BASIC B
						0.3.4 END
						0.4 OR C_zero_or_more_times_
						0.4.1 START
						0.4.2 CONDITION
						0.4.3 BASIC C
						0.4.4 END
						0.5 END
						=> 0.1->0.2 0.2->0.3 0.2->0.4 0.3->0.5 0.4->0.5 0.3.1->0.3.2 0.3.2->0.3.3 0.3.2->0.3.4 0.3.3->0.3.4 0.4.1->0.4.2 0.4.2->0.4.3 0.4.3->0.4.3 0.4.2->0.4.4 0.4.3->0.4.4"""));
	}

	@ParameterizedTest(name = "{0}")
	@MethodSource("formulas")
	void transformsByTheRulesOfTheOriginal(String formula, String expected) {
		Model model = Statecharts.transform(formula);
		String[] parts = expected.split("\n=> ");
		String[] actual = Statecharts.render(model).split("\n");
		List<String> states = new ArrayList<>();
		Set<String> transitions = new TreeSet<>();
		for (String line : actual) {
			if (line.contains("->")) {
				transitions.add(line);
			} else {
				states.add(line);
			}
		}
		assertEquals(parts[0], String.join("\n", states), "states of " + formula);
		assertEquals(new TreeSet<>(Arrays.asList(parts[1].split(" "))), transitions, "transitions of " + formula);
		assertEquals(parts[1].split(" ").length, model.getTransitions().size(), "no duplicate transitions");
	}
}
