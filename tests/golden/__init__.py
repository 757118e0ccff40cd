"""Golden output: the every-feature fixture spec rendered by the four back ends, checked in."""
