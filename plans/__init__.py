"""plans: velocity and acceleration plans of planar linkages."""
