"""Shared meshes and arrangements for the surface tests (module-scoped: computed once)."""

from __future__ import annotations

import pytest
import trimesh

from strew import Shape
from strew import surface


@pytest.fixture(scope="session")
def sphere() -> trimesh.Trimesh:
    return trimesh.creation.icosphere(subdivisions=4)  # 5,120 faces, radius 1


@pytest.fixture(scope="session")
def torus() -> trimesh.Trimesh:
    return trimesh.creation.torus(1.0, 0.4, major_sections=64, minor_sections=32)


@pytest.fixture(scope="session")
def sphere_dots(sphere):
    return surface.pack(0.05, sphere, rng=1)


@pytest.fixture(scope="session")
def torus_mixed(torus):
    lib = {"leaf": Shape.polygon([(-3, 0), (0, 1), (3, 0), (0, -1)]), "dot": Shape.circle(1.0)}
    return surface.pack(lib, torus, scale=(0.02, 0.035), rng=7, rotation="random")
