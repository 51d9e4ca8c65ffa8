package org.kse.notation;

/** Where a state is drawn: its top-left corner relative to its parent state's top-left corner, and its size (pixels). */
public record Bounds(double x, double y, double width, double height) {

	public double right() {
		return x + width;
	}

	public double bottom() {
		return y + height;
	}

	/** The two rectangles share more than an edge. */
	public boolean overlaps(Bounds other) {
		return x < other.right() && other.x < right() && y < other.bottom() && other.y < bottom();
	}
}
