"""Finite symmetry groups acting on leg-grouped arrays shaped (..., n_legs, n_features).

An element is a leg permutation together with a representation inside a leg. Rotations
relabel legs only. A reflection (about a vertical plane through the base) also mirrors each
leg in its own x-z plane, which flips features by geometric type; the per-feature signs come
from the schema (`Layout.reflection_signs`), so one element acts on inputs and targets alike.

Groups are generated from generators by closure, so the cyclic, dihedral and Klein-4 groups
all come from the same code, and the group axioms are checked by tests, not assumed.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from symbench.core.common.errors import SymbenchError


@dataclass(frozen=True)
class GroupElement:
    """Carries leg i to leg perm[i]; `reflect` says whether it mirrors the robot."""

    perm: tuple[int, ...]
    reflect: bool = False
    label: str = field(default="", compare=False)

    def __post_init__(self) -> None:
        if sorted(self.perm) != list(range(len(self.perm))):
            raise SymbenchError(f"group element {self.perm} is not a permutation of legs")

    @property
    def n_legs(self) -> int:
        return len(self.perm)

    def __mul__(self, other: GroupElement) -> GroupElement:
        """Composition: (g * h) acts as h first, then g."""
        if other.n_legs != self.n_legs:
            raise SymbenchError("cannot compose elements acting on different numbers of legs")
        perm = tuple(self.perm[other.perm[i]] for i in range(self.n_legs))
        return GroupElement(perm, self.reflect != other.reflect)

    def inverse(self) -> GroupElement:
        inv = [0] * self.n_legs
        for i, j in enumerate(self.perm):
            inv[j] = i
        return GroupElement(tuple(inv), self.reflect)

    def source_legs(self) -> np.ndarray:
        """Index array `src` with (g . x)[..., j, :] = rho(x[..., src[j], :])."""
        return np.asarray(self.inverse().perm, dtype=np.int64)

    def permutation_matrix(self) -> np.ndarray:
        """P with (g . x) = P @ x over the leg axis (before the in-leg representation)."""
        p = np.zeros((self.n_legs, self.n_legs))
        p[list(self.perm), list(range(self.n_legs))] = 1.0
        return p

    @property
    def name(self) -> str:
        """'identity', 'shift k' (a rotation by k legs), 'mirror k' (legs i -> k - i), else
        the permutation."""
        n, k = self.n_legs, self.perm[0]
        if not self.reflect and all(p == (i + k) % n for i, p in enumerate(self.perm)):
            return "identity" if k == 0 else f"shift {k}"
        if self.reflect and all(p == (k - i) % n for i, p in enumerate(self.perm)):
            return f"mirror {k}"
        return str(self.perm)

    def __repr__(self) -> str:
        return self.label or f"GroupElement(perm={self.perm}, reflect={self.reflect})"


class LegGroup:
    """A finite group of leg permutations (with optional reflection), closed by construction."""

    def __init__(self, name: str, generators: Sequence[GroupElement], max_order: int = 1000):
        if not generators:
            raise SymbenchError(f"group {name}: at least one generator is needed")
        n = generators[0].n_legs
        if any(g.n_legs != n for g in generators):
            raise SymbenchError(f"group {name}: generators act on different numbers of legs")
        self.name = name
        self.n_legs = n
        self.generators = tuple(generators)
        self.elements = self._close(generators, max_order)
        self._index = {e: i for i, e in enumerate(self.elements)}

    @staticmethod
    def _close(generators: Sequence[GroupElement], max_order: int) -> tuple[GroupElement, ...]:
        """Breadth-first closure under multiplication by generators; identity first."""
        n = generators[0].n_legs
        identity = GroupElement(tuple(range(n)), False, "e")
        found = [identity]
        seen = {identity}
        frontier = [identity]
        while frontier:
            nxt = []
            for a in frontier:
                for g in generators:
                    b = g * a
                    if b not in seen:
                        seen.add(b)
                        found.append(b)
                        nxt.append(b)
                        if len(found) > max_order:
                            raise SymbenchError(f"group closure exceeded {max_order} elements")
            frontier = nxt
        return tuple(found)

    # --- group structure -------------------------------------------------------------
    @property
    def identity(self) -> GroupElement:
        return self.elements[0]

    @property
    def order(self) -> int:
        return len(self.elements)

    @property
    def rotation_order(self) -> int:
        """Number of pure rotations (the identity included): the sector is 360 / this degrees."""
        return sum(1 for e in self.elements if not e.reflect)

    @property
    def has_reflections(self) -> bool:
        return any(e.reflect for e in self.elements)

    def __iter__(self) -> Iterator[GroupElement]:
        return iter(self.elements)

    def __len__(self) -> int:
        return len(self.elements)

    def __contains__(self, g: object) -> bool:
        return g in self._index

    def index(self, g: GroupElement) -> int:
        return self._index[g]

    def cayley_table(self) -> np.ndarray:
        """table[i, j] = index of elements[i] * elements[j]."""
        return np.array([[self._index[a * b] for b in self.elements] for a in self.elements])

    # --- action ------------------------------------------------------------------------
    def act(
        self, g: GroupElement, x: Any, reflection_signs: Sequence[float] | np.ndarray | None = None
    ) -> Any:
        """g . x for a numpy, torch or JAX array shaped (..., n_legs, n_features).

        `reflection_signs` (one per feature, from the schema) is required when g reflects.
        The result has the input's type, dtype and device.
        """
        if g not in self._index:
            raise SymbenchError(f"{g!r} is not an element of {self.name}")
        return act(g, x, reflection_signs)

    def __repr__(self) -> str:
        return f"LegGroup({self.name}, order={self.order}, legs={self.n_legs})"


def act(
    g: GroupElement, x: Any, reflection_signs: Sequence[float] | np.ndarray | None = None
) -> Any:
    """Apply g to an array shaped (..., n_legs, n_features) of numpy, torch or JAX."""
    shape = tuple(x.shape)
    if len(shape) < 2 or shape[-2] != g.n_legs:
        raise SymbenchError(
            f"expected an array shaped (..., {g.n_legs} legs, features), got {shape}"
        )
    src = g.source_legs()
    backend = type(x).__module__.split(".")[0]
    if backend == "torch":
        import torch

        y = x.index_select(-2, torch.as_tensor(src, device=x.device))
    else:  # numpy and jax index alike
        y = x[..., src, :]
    if not g.reflect:
        return y
    if reflection_signs is None:
        raise SymbenchError("a reflection needs the layout's reflection signs to act")
    signs = np.asarray(reflection_signs, dtype=np.float64)
    if signs.shape != (shape[-1],):
        raise SymbenchError(f"{signs.size} reflection signs for {shape[-1]} features")
    if backend == "torch":
        import torch

        return y * torch.as_tensor(signs, dtype=x.dtype, device=x.device)
    if backend in ("jax", "jaxlib"):
        import jax.numpy as jnp

        return y * jnp.asarray(signs, dtype=x.dtype)
    return y * signs.astype(x.dtype, copy=False)


# --- constructors -------------------------------------------------------------------------
def shift(n_legs: int, k: int) -> GroupElement:
    """Rotation carrying leg i to leg i + k (legs numbered counter-clockwise)."""
    return GroupElement(tuple((i + k) % n_legs for i in range(n_legs)), False, f"r^{k}")


def mirror(n_legs: int, offset: int) -> GroupElement:
    """Reflection carrying leg i to leg (offset - i) mod n, mirroring each leg."""
    return GroupElement(tuple((offset - i) % n_legs for i in range(n_legs)), True, f"s{offset}")


def cyclic(n_legs: int, k: int = 1, name: str | None = None) -> LegGroup:
    """Rotations generated by a k-leg shift: order n_legs / gcd(n_legs, k)."""
    _check_legs(n_legs, k)
    order = n_legs // np.gcd(n_legs, k)
    return LegGroup(name or f"C{order}", [shift(n_legs, k)])


def dihedral(n_legs: int, k: int = 1, mirror_offset: int = 0, name: str | None = None) -> LegGroup:
    """Rotations by a k-leg shift and the mirror i -> mirror_offset - i."""
    _check_legs(n_legs, k)
    order = 2 * (n_legs // np.gcd(n_legs, k))
    return LegGroup(name or f"D{order // 2}", [shift(n_legs, k), mirror(n_legs, mirror_offset)])


def klein4() -> LegGroup:
    """Klein four-group of a 4-leg robot with two mirror planes (legs CCW from front-left).

    The sagittal mirror swaps legs 0<->3 and 1<->2, the coronal one 0<->1 and 2<->3; their
    product is the rotation by 180 degrees (a shift by 2 legs).
    """
    return LegGroup("K4", [mirror(4, 3), mirror(4, 1)])


def _check_legs(n_legs: int, k: int) -> None:
    if n_legs < 1:
        raise SymbenchError(f"a group needs at least one leg, got {n_legs}")
    if k % n_legs == 0 and n_legs > 1:
        raise SymbenchError(f"a shift by {k} legs of a {n_legs}-leg robot is the identity")


def from_spec(n_legs: int, kind: str, shift_legs: int = 1, mirror_offset: int = 0) -> LegGroup:
    """Build the group a robot spec names: kind is 'cyclic', 'dihedral' or 'klein4'."""
    if kind == "cyclic":
        return cyclic(n_legs, shift_legs)
    if kind == "dihedral":
        return dihedral(n_legs, shift_legs, mirror_offset)
    if kind == "klein4":
        if n_legs != 4:
            raise SymbenchError(f"klein4 acts on 4 legs, the robot has {n_legs}")
        return klein4()
    raise SymbenchError(f"unknown symmetry group kind '{kind}' (cyclic, dihedral, klein4)")
