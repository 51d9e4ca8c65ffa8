package org.kse.notation;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Function;

import org.eclipse.emf.ecore.EObject;
import org.kse.model.statechart.Model;
import org.kse.model.statechart.Node;
import org.kse.model.statechart.Transition;

/**
 * Where the transitions of a diagram run and where their labels go, from wherever the states are
 * (arranged, read from a file, or moved by hand): each transition takes the shortest of a few
 * orthogonal routes that crosses the fewest states, and its label the first place along it, or
 * else nearest to it, that lies on no state and on no other label. A label may lie on the states
 * that hold both ends of its transition (below their header), on no other.
 * The diagram editor and the SVG export both draw from this, so they look alike.
 */
public final class TransitionLayout {

	/** Font size (px) of a transition's label, as the diagram draws it ({@link NotationStyle#transitionLabel()}). */
	public static final double LABEL_FONT_SIZE = NotationStyle.get().transitionLabel().size();
	/** Height of a label's box: one line of {@link #LABEL_FONT_SIZE}. */
	public static final double LABEL_HEIGHT = 15;
	/** Longer expressions are cut (with an ellipsis) in the label; hovering shows all of them. */
	public static final int LABEL_MAX_CHARACTERS = 36;

	/** Room kept between a label and whatever it must not cover. */
	private static final double LABEL_GAP = 3;
	/** How far a line keeps from the states it goes around. */
	private static final double DETOUR = 14;
	/** The farthest (px) a label is searched for from its transition before it is left on it. */
	private static final double SEARCH_RADIUS = 900;

	/**
	 * One transition as drawn: its bend points (absolute; the line runs from the source's border
	 * through them to the target's border, leaving and entering the states through their centres),
	 * the text of its label and the label's box (absolute; null when it has no text).
	 */
	public record Placed(List<double[]> bends, String text, Bounds label) {
	}

	private TransitionLayout() {
	}

	/** The text a transition's label shows: the first line of its expression, cut when long. */
	public static String labelText(Transition transition) {
		String expression = transition.getTE() == null ? "" : transition.getTE().strip();
		String firstLine = expression.lines().findFirst().orElse("").strip();
		boolean more = expression.lines().count() > 1;
		if (firstLine.length() > LABEL_MAX_CHARACTERS) {
			firstLine = firstLine.substring(0, LABEL_MAX_CHARACTERS - 1).strip();
			more = true;
		}
		return more ? firstLine + " …" : firstLine;
	}

	/** The size a label is drawn at: wide enough for DejaVu Sans, the widest of the fonts the diagram asks for. */
	public static Bounds labelSize(String text) {
		return new Bounds(0, 0, TextWidth.of(text, LABEL_FONT_SIZE, NotationStyle.get().transitionLabel().bold()) + 4, LABEL_HEIGHT);
	}

	/** Every transition of the model whose ends are states, with states placed at {@code relative} (to their parents). */
	public static Map<Transition, Placed> of(Model model, Function<Node, Bounds> relative) {
		Map<Node, Bounds> boxes = new IdentityHashMap<>();
		BoxIndex<Node> states = new BoxIndex<>();
		for (Node root : model.getNodes()) {
			place(root, 0, 0, relative, boxes, states);
		}
		BoxIndex<Object> labels = new BoxIndex<>();
		Map<Transition, Placed> placed = new LinkedHashMap<>();
		Map<String, Integer> parallels = new HashMap<>();
		for (Transition transition : model.getTransitions()) {
			Node source = transition.getSource();
			Node target = transition.getTarget();
			if (source == null || target == null || !boxes.containsKey(source) || !boxes.containsKey(target)) {
				continue;
			}
			// transitions between the same two states run side by side, not on one line
			String pair = System.identityHashCode(source) < System.identityHashCode(target)
					? System.identityHashCode(source) + ":" + System.identityHashCode(target)
					: System.identityHashCode(target) + ":" + System.identityHashCode(source);
			int parallel = parallels.merge(pair, 1, Integer::sum) - 1;
			Set<Node> holders = holders(source, target);
			List<double[]> bends = route(source, target, boxes, states, holders, parallel);
			String text = labelText(transition);
			Bounds label = null;
			if (!text.isEmpty()) {
				label = placeLabel(text, polyline(boxes.get(source), boxes.get(target), bends), boxes, states, labels, holders);
				labels.add(label, transition);
			}
			placed.put(transition, new Placed(bends, text, label));
		}
		return placed;
	}

	private static void place(Node node, double originX, double originY, Function<Node, Bounds> relative, Map<Node, Bounds> boxes, BoxIndex<Node> states) {
		Bounds own = relative.apply(node);
		Bounds absolute = new Bounds(originX + own.x(), originY + own.y(), own.width(), own.height());
		boxes.put(node, absolute);
		states.add(absolute, node);
		for (Node child : node.getChildren()) {
			place(child, absolute.x(), absolute.y(), relative, boxes, states);
		}
	}

	/** The states that hold both ends (a transition's line and label may lie on them). */
	private static Set<Node> holders(Node source, Node target) {
		Set<Node> ofSource = Collections.newSetFromMap(new IdentityHashMap<>());
		for (EObject each = source; each instanceof Node node; each = node.eContainer()) {
			ofSource.add(node);
		}
		Set<Node> both = Collections.newSetFromMap(new IdentityHashMap<>());
		// a transition from a state to itself runs outside it: the state does not hold it
		for (EObject each = source == target ? target.eContainer() : target; each instanceof Node node; each = node.eContainer()) {
			if (ofSource.contains(node)) {
				both.add(node);
			}
		}
		return both;
	}

	// --- routes

	private static List<double[]> route(Node source, Node target, Map<Node, Bounds> boxes, BoxIndex<Node> states, Set<Node> holders, int parallel) {
		Bounds s = boxes.get(source);
		Bounds t = boxes.get(target);
		double shift = parallel * 10.0;
		if (source == target) {
			double x = s.right() - Math.min(12, s.width() / 4) - shift;
			double above = s.y() - 18 - shift;
			double right = s.right() + 18 + shift;
			return List.of(new double[] { x, above }, new double[] { right, above }, new double[] { right, s.y() + Math.min(14, s.height() / 2) });
		}
		if (holders.contains(source) || holders.contains(target)) {
			return List.of();
		}
		double sx = centreX(s);
		double sy = centreY(s);
		double tx = centreX(t);
		double ty = centreY(t);
		List<List<double[]>> candidates = new ArrayList<>();
		candidates.add(List.of());
		if (t.x() > s.right() || s.x() > t.right()) {
			double middle = t.x() > s.right() ? (s.right() + t.x()) / 2 : (t.right() + s.x()) / 2;
			candidates.add(List.of(new double[] { middle + shift, sy }, new double[] { middle + shift, ty }));
		}
		if (t.y() > s.bottom() || s.y() > t.bottom()) {
			double middle = t.y() > s.bottom() ? (s.bottom() + t.y()) / 2 : (t.bottom() + s.y()) / 2;
			candidates.add(List.of(new double[] { sx, middle + shift }, new double[] { tx, middle + shift }));
		}
		if ((tx > s.right() || tx < s.x()) && (sy > t.bottom() || sy < t.y())) {
			candidates.add(List.of(new double[] { tx, sy }));
		}
		if ((sx > t.right() || sx < t.x()) && (ty > s.bottom() || ty < s.y())) {
			candidates.add(List.of(new double[] { sx, ty }));
		}
		List<double[]> best = cheapest(candidates, source, target, s, t, boxes, states, holders);
		if (best != null) {
			return best;
		}
		// every direct way crosses a state: around whatever lies between, above, below, left or right of it
		Bounds span = union(s, t);
		double top = span.y();
		double bottom = span.bottom();
		double left = span.x();
		double right = span.right();
		for (Node other : states.near(span)) {
			if (other != source && other != target && !holders.contains(other)) {
				Bounds o = boxes.get(other);
				if (o.overlaps(span)) {
					top = Math.min(top, o.y());
					bottom = Math.max(bottom, o.bottom());
					left = Math.min(left, o.x());
					right = Math.max(right, o.right());
				}
			}
		}
		candidates.add(List.of(new double[] { sx, top - DETOUR - shift }, new double[] { tx, top - DETOUR - shift }));
		candidates.add(List.of(new double[] { sx, bottom + DETOUR + shift }, new double[] { tx, bottom + DETOUR + shift }));
		candidates.add(List.of(new double[] { left - DETOUR - shift, sy }, new double[] { left - DETOUR - shift, ty }));
		candidates.add(List.of(new double[] { right + DETOUR + shift, sy }, new double[] { right + DETOUR + shift, ty }));
		best = cheapest(candidates, source, target, s, t, boxes, states, holders);
		return best != null ? best : leastCrossing(candidates, source, target, s, t, boxes, states, holders);
	}

	/**
	 * The cheapest of the routes that cross no state, or null. A bend costs a little, a slanted line
	 * more than a bend; routes are tried from the cheapest, so most transitions try one or two.
	 */
	private static List<double[]> cheapest(List<List<double[]>> candidates, Node source, Node target, Bounds s, Bounds t, Map<Node, Bounds> boxes,
			BoxIndex<Node> states, Set<Node> holders) {
		List<List<double[]>> byCost = new ArrayList<>(candidates);
		Map<List<double[]>, Double> costs = new IdentityHashMap<>();
		for (List<double[]> bends : candidates) {
			costs.put(bends, baseCost(s, t, bends));
		}
		byCost.sort((a, b) -> Double.compare(costs.get(a), costs.get(b)));
		for (List<double[]> bends : byCost) {
			if (crossed(polyline(s, t, bends), source, target, boxes, states, holders) == 0) {
				return bends;
			}
		}
		return null;
	}

	/** When every route crosses some state: the one that crosses fewest. */
	private static List<double[]> leastCrossing(List<List<double[]>> candidates, Node source, Node target, Bounds s, Bounds t, Map<Node, Bounds> boxes,
			BoxIndex<Node> states, Set<Node> holders) {
		List<double[]> best = candidates.get(0);
		double bestCost = Double.POSITIVE_INFINITY;
		for (List<double[]> bends : candidates) {
			double cost = crossed(polyline(s, t, bends), source, target, boxes, states, holders) * 100_000 + baseCost(s, t, bends);
			if (cost < bestCost) {
				bestCost = cost;
				best = bends;
			}
		}
		return best;
	}

	private static double baseCost(Bounds s, Bounds t, List<double[]> bends) {
		List<double[]> line = polyline(s, t, bends);
		double cost = 0;
		for (int i = 0; i + 1 < line.size(); i++) {
			cost += length(line, i);
		}
		boolean slanted = bends.isEmpty() && Math.abs(centreX(s) - centreX(t)) > 0.5 && Math.abs(centreY(s) - centreY(t)) > 0.5;
		return cost + bends.size() * 24 + (slanted ? 60 : 0);
	}

	/** How many states the line passes over (other than its ends and the states holding it). */
	private static int crossed(List<double[]> line, Node source, Node target, Map<Node, Bounds> boxes, BoxIndex<Node> states, Set<Node> holders) {
		Set<Node> crossed = Collections.newSetFromMap(new IdentityHashMap<>());
		for (int i = 0; i + 1 < line.size(); i++) {
			double[] a = line.get(i);
			double[] b = line.get(i + 1);
			for (Node other : states.near(segmentBox(a, b))) {
				if (other != source && other != target && !holders.contains(other) && crosses(a, b, boxes.get(other))) {
					crossed.add(other);
				}
			}
		}
		return crossed.size();
	}

	/** The line as drawn: from the source's border through the bends to the target's border. */
	private static List<double[]> polyline(Bounds s, Bounds t, List<double[]> bends) {
		List<double[]> line = new ArrayList<>();
		double[] first = bends.isEmpty() ? new double[] { centreX(t), centreY(t) } : bends.get(0);
		double[] last = bends.isEmpty() ? new double[] { centreX(s), centreY(s) } : bends.get(bends.size() - 1);
		line.add(border(s, first));
		line.addAll(bends);
		line.add(border(t, last));
		return line;
	}

	/** Where the line from the centre of a box towards a point leaves the box. */
	static double[] border(Bounds box, double[] toward) {
		double cx = centreX(box);
		double cy = centreY(box);
		double dx = toward[0] - cx;
		double dy = toward[1] - cy;
		if (dx == 0 && dy == 0) {
			return new double[] { cx, cy };
		}
		double scale = Math.min(1, 1 / Math.max(Math.abs(dx) / (box.width() / 2), Math.abs(dy) / (box.height() / 2)));
		return new double[] { cx + dx * scale, cy + dy * scale };
	}

	/** Whether the segment passes through the inside of the box (touching its border does not count). */
	private static boolean crosses(double[] a, double[] b, Bounds box) {
		double x0 = box.x() + 1;
		double y0 = box.y() + 1;
		double x1 = box.right() - 1;
		double y1 = box.bottom() - 1;
		if (x1 <= x0 || y1 <= y0) {
			return false;
		}
		// Liang–Barsky clipping of the segment to the box
		double dx = b[0] - a[0];
		double dy = b[1] - a[1];
		double enter = 0;
		double leave = 1;
		double[] p = { -dx, dx, -dy, dy };
		double[] q = { a[0] - x0, x1 - a[0], a[1] - y0, y1 - a[1] };
		for (int i = 0; i < 4; i++) {
			if (p[i] == 0) {
				if (q[i] < 0) {
					return false;
				}
			} else {
				double r = q[i] / p[i];
				if (p[i] < 0) {
					enter = Math.max(enter, r);
				} else {
					leave = Math.min(leave, r);
				}
			}
		}
		return enter < leave;
	}

	// --- labels

	private static Bounds placeLabel(String text, List<double[]> line, Map<Node, Bounds> boxes, BoxIndex<Node> states, BoxIndex<Object> labels,
			Set<Node> holders) {
		Bounds size = labelSize(text);
		double w = size.width();
		double h = size.height();
		List<Integer> segments = new ArrayList<>();
		for (int i = 0; i + 1 < line.size(); i++) {
			segments.add(i);
		}
		// the longest stretch of the line first: that is where a reader looks for its label
		segments.sort((i, j) -> Double.compare(length(line, j), length(line, i)));
		double[] fractions = { 0.5, 0.35, 0.65, 0.2, 0.8 };
		for (int i : segments) {
			double[] a = line.get(i);
			double[] b = line.get(i + 1);
			boolean horizontal = Math.abs(b[1] - a[1]) < 0.5;
			boolean vertical = Math.abs(b[0] - a[0]) < 0.5;
			for (double f : fractions) {
				double x = a[0] + (b[0] - a[0]) * f;
				double y = a[1] + (b[1] - a[1]) * f;
				List<Bounds> sides = new ArrayList<>(2);
				if (horizontal) {
					sides.add(new Bounds(x - w / 2, y - LABEL_GAP - h, w, h));
					sides.add(new Bounds(x - w / 2, y + LABEL_GAP, w, h));
				} else if (vertical) {
					sides.add(new Bounds(x + LABEL_GAP + 1, y - h / 2, w, h));
					sides.add(new Bounds(x - LABEL_GAP - 1 - w, y - h / 2, w, h));
				} else {
					sides.add(new Bounds(x + LABEL_GAP, y - LABEL_GAP - h, w, h));
					sides.add(new Bounds(x - LABEL_GAP - w, y + LABEL_GAP, w, h));
				}
				for (Bounds candidate : sides) {
					if (free(candidate, boxes, states, labels, holders)) {
						return candidate;
					}
				}
			}
		}
		// nowhere along the line: the nearest free place around its middle
		double[] middle = pointAt(line, 0.5);
		for (double radius = 8; radius <= SEARCH_RADIUS; radius += 8) {
			int steps = Math.max(8, (int) (2 * Math.PI * radius / 8));
			for (int k = 0; k < steps; k++) {
				double angle = -Math.PI / 2 + 2 * Math.PI * k / steps;
				Bounds candidate = new Bounds(middle[0] + radius * Math.cos(angle) - w / 2, middle[1] + radius * Math.sin(angle) - h / 2, w, h);
				if (free(candidate, boxes, states, labels, holders)) {
					return candidate;
				}
			}
		}
		return new Bounds(middle[0] - w / 2, middle[1] - h / 2, w, h);
	}

	private static boolean free(Bounds candidate, Map<Node, Bounds> boxes, BoxIndex<Node> states, BoxIndex<Object> labels, Set<Node> holders) {
		Bounds around = new Bounds(candidate.x() - LABEL_GAP, candidate.y() - LABEL_GAP, candidate.width() + 2 * LABEL_GAP,
				candidate.height() + 2 * LABEL_GAP);
		for (Node state : states.near(around)) {
			Bounds box = boxes.get(state);
			if (holders.contains(state)) {
				// within a state that holds the transition, but not on its name
				Bounds header = new Bounds(box.x(), box.y(), box.width(), Math.min(box.height(), Arrange.HEADER));
				if (header.overlaps(around) || !inside(candidate, box)) {
					return false;
				}
			} else if (box.overlaps(around)) {
				return false;
			}
		}
		for (Object other : labels.near(around)) {
			if (labels.boxOf(other).overlaps(around)) {
				return false;
			}
		}
		return true;
	}

	private static boolean inside(Bounds inner, Bounds outer) {
		return inner.x() >= outer.x() && inner.y() >= outer.y() && inner.right() <= outer.right() && inner.bottom() <= outer.bottom();
	}

	private static double length(List<double[]> line, int segment) {
		double[] a = line.get(segment);
		double[] b = line.get(segment + 1);
		return Math.hypot(b[0] - a[0], b[1] - a[1]);
	}

	private static double[] pointAt(List<double[]> line, double fraction) {
		double total = 0;
		for (int i = 0; i + 1 < line.size(); i++) {
			total += length(line, i);
		}
		double wanted = total * fraction;
		for (int i = 0; i + 1 < line.size(); i++) {
			double each = length(line, i);
			if (wanted <= each && each > 0) {
				double[] a = line.get(i);
				double[] b = line.get(i + 1);
				return new double[] { a[0] + (b[0] - a[0]) * wanted / each, a[1] + (b[1] - a[1]) * wanted / each };
			}
			wanted -= each;
		}
		return line.get(line.size() - 1);
	}

	private static double centreX(Bounds box) {
		return box.x() + box.width() / 2;
	}

	private static double centreY(Bounds box) {
		return box.y() + box.height() / 2;
	}

	private static Bounds union(Bounds a, Bounds b) {
		double x = Math.min(a.x(), b.x());
		double y = Math.min(a.y(), b.y());
		return new Bounds(x, y, Math.max(a.right(), b.right()) - x, Math.max(a.bottom(), b.bottom()) - y);
	}

	private static Bounds segmentBox(double[] a, double[] b) {
		double x = Math.min(a[0], b[0]);
		double y = Math.min(a[1], b[1]);
		return new Bounds(x, y, Math.abs(b[0] - a[0]), Math.abs(b[1] - a[1]));
	}

	/** Boxes in a grid of cells, so that what lies near a box is found without looking at every box. */
	private static final class BoxIndex<T> {
		private static final double CELL = 128;
		private final Map<Long, List<T>> cells = new HashMap<>();
		private final Map<T, Bounds> boxes = new IdentityHashMap<>();

		void add(Bounds box, T item) {
			boxes.put(item, box);
			forCells(box, key -> cells.computeIfAbsent(key, k -> new ArrayList<>()).add(item));
		}

		Bounds boxOf(T item) {
			return boxes.get(item);
		}

		/** The items whose cells the box touches (a superset of those it overlaps), each once. */
		Set<T> near(Bounds box) {
			Set<T> found = Collections.newSetFromMap(new IdentityHashMap<>());
			forCells(box, key -> {
				List<T> items = cells.get(key);
				if (items != null) {
					found.addAll(items);
				}
			});
			return found;
		}

		private static void forCells(Bounds box, java.util.function.LongConsumer action) {
			long x0 = (long) Math.floor(box.x() / CELL);
			long x1 = (long) Math.floor(box.right() / CELL);
			long y0 = (long) Math.floor(box.y() / CELL);
			long y1 = (long) Math.floor(box.bottom() / CELL);
			for (long x = x0; x <= x1; x++) {
				for (long y = y0; y <= y1; y++) {
					action.accept(x * 4_000_003L + y);
				}
			}
		}
	}
}
