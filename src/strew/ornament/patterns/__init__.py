"""Built-in rule files: ``dots``, ``flowers``, ``spirals``, ``hierarchy``, ``vase``, ``willow``.

Each module is a plain rule file (it could be passed as a path to ``strew ornament``)
that assigns ``pattern = Pattern(...)``; read them as examples of how to write one.
"""
