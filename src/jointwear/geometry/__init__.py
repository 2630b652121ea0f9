"""Geometry of the joint: bushing contour, pin, penetration, contour update."""

from jointwear.geometry.contour import BushingContour, Pin, node_angles

__all__ = ["BushingContour", "Pin", "node_angles"]
