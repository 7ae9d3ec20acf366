"""Gallery sections of the foundation (see :mod:`strew.demo`)."""
