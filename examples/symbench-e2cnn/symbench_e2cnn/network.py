"""e2cnn-mlp: a multi-layer perceptron whose layers are e2cnn's group-equivariant linear maps.

The robot's rotation group is a cyclic group C_m of turns about the base normal, and in the
leg-grouped view it only relabels legs: every input column (joint states, and the base's
velocities, acceleration, gravity and position expressed in each leg's own frame) and every
torque is a per-leg quantity, so a turn by one step of C_m moves leg i's row to leg
i + n_legs / m and changes nothing inside a row. The legs therefore carry a permutation
representation of C_m. It is free (no turn but the identity fixes a leg), so it is
n_legs / m copies of C_m's regular representation, one per orbit of legs; every feature
column contributes these copies, and there is no invariant (trivial) field, because no
input column is shared by all legs. On the built-in robots (`robots/*/robot.toml`): hexa
is C6 (shift 1) and nona C9 (shift 1), one regular field per column; magneto is C2
(shift 2), two regular fields per column (orbits legs {0, 2} and {1, 3}).

The network is built with e2cnn (QUVA-Lab), which parametrizes the most general
equivariant linear map between two field types. Each layer is `e2cnn.nn.R2Conv` with a
1x1 kernel on a one-pixel image, i.e. the equivariant linear maps on the fibre (escnn's
`Linear` on `no_base_space`); the nonlinearity is `e2cnn.nn.ELU`, pointwise, which
commutes with the permutations of a regular field. The input field type is `fields`
copies of nothing but the regular representation of `gspaces.Rot2dOnR2(m)`; this module
maps symbench's `(N, legs, F)` arrays to and from e2cnn's flat field layout, the library
builds the weight sharing. Hidden layers are `fields` regular fields (`fields * m` units),
the output 3 regular fields per orbit (coxa, femur and tibia torques).

Which group: `order` m (0: n_legs) picks C_m, acting by the shift of n_legs / m legs, for m
dividing n_legs. The network cannot see the robot, only its number of legs, so the default
is the largest rotation group the legs admit, C_n_legs: exactly the robot's group on hexa
and nona; on magneto C4, which contains its C2 (the legs are not 90 degrees apart, so C4 is
more than magneto's physics has; `order=2` gives exactly C2).

How it differs from sdnn: sdnn shares one MLP across legs and sums over them, so it is
equivariant to every permutation of the legs (n_legs! of them), of which the robot's
rotations are a few. This network is equivariant to the cyclic group C_m only, as e2cnn
builds it: a leg's neighbours are distinguishable, and its weights are the most general
C_m-equivariant linear maps rather than one shared per-leg map. Neither is equivariant to
the robot's mirrors (sdnn only with `mirror=1`).

Two details keep e2cnn's layers compatible with symbench's checkpoints and the kit: the
layers never switch to e2cnn's evaluation mode (which caches the expanded filter and
changes the module's saved tensors), and the library's fixed tensors (the sampled basis,
the bias expansion) are non-persistent buffers. The saved parameters are the library's
learnable coefficients only, so any values of them (perturbed by the kit, rounded to
float32 in a checkpoint) give an equivariant network.
"""

from __future__ import annotations

import warnings

import torch
from e2cnn import gspaces
from e2cnn import nn as enn
from torch import nn

from symbench import ModelDims, SymbenchError

JOINT_TORQUES = 3  # coxa, femur, tibia per leg


def rotation_order(n_legs: int, order: int) -> int:
    """The order m of the cyclic group the network is built for (0: n_legs)."""
    m = n_legs if order == 0 else order
    if m < 2 or n_legs % m:
        raise SymbenchError(
            f"e2cnn-mlp: order {order} is not a divisor of the robot's {n_legs} legs above 1 "
            "(0 uses the number of legs)"
        )
    return m


def linear(in_type: enn.FieldType, out_type: enn.FieldType) -> enn.R2Conv:
    """The most general equivariant linear map from `in_type` to `out_type`: a 1x1 kernel.

    `recompute`: a basis of its own. By default e2cnn shares one basis module between all
    layers of the same types, in every network of the process, so converting one network
    (`.double()`) would convert the others' bases too."""
    return enn.R2Conv(in_type, out_type, kernel_size=1, recompute=True)


class E2cnnMLP(nn.Module):
    """`layers` hidden layers of `fields` regular fields of C_m, ELU, equivariant output.

    `input_repr` is "regular" (the true action on the legs); "irrep1" declares the inputs
    to turn like planar vectors (C_m's frequency-1 irreducible representation), a
    deliberately wrong type that only the tests' control uses.
    """

    def __init__(
        self,
        n_legs: int,
        n_features: int,
        order: int,
        fields: int,
        layers: int,
        input_repr: str = "regular",
    ):
        super().__init__()
        self.n_legs, self.n_features = n_legs, n_features
        self.order = rotation_order(n_legs, order)
        self.orbits = n_legs // self.order
        gspace = gspaces.Rot2dOnR2(self.order)
        regular = gspace.regular_repr
        given = {"regular": regular, "irrep1": gspace.irrep(1)}[input_repr]
        self.in_type = enn.FieldType(gspace, [given] * (n_features * n_legs // given.size))
        hidden = enn.FieldType(gspace, [regular] * fields)
        out_type = enn.FieldType(gspace, [regular] * (JOINT_TORQUES * self.orbits))
        modules: list[enn.EquivariantModule] = []
        previous = self.in_type
        with warnings.catch_warnings():  # e2cnn indexes with uint8 masks when it builds a basis
            warnings.filterwarnings("ignore", "indexing with dtype torch.uint8", UserWarning)
            for _ in range(layers):
                modules += [linear(previous, hidden), enn.ELU(hidden)]
                previous = hidden
            modules.append(linear(previous, out_type))
        self.net = enn.SequentialModule(*modules)
        self.net.train(True)  # drops the filter caches R2Conv allocates for evaluation mode
        for module in self.net.modules():
            for name, buffer in list(module.named_buffers(recurse=False)):
                module.register_buffer(name, buffer, persistent=False)

    def train(self, mode: bool = True) -> E2cnnMLP:
        """Sets this module's mode only: the e2cnn layers always expand their coefficients
        (their evaluation mode would cache the filter and save it with the parameters)."""
        self.training = mode
        return self

    def forward(self, x: torch.Tensor) -> torch.Tensor:  # (N, legs, F) -> (N, legs, 3)
        n = x.shape[0]
        # leg h * orbits + o is element h of orbit o's regular field; C_m's generator maps
        # leg i to leg i + orbits, which is element h to h + 1: the regular representation
        fibre = x.reshape(n, self.order, self.orbits, self.n_features).permute(0, 3, 2, 1)
        fibre = fibre.reshape(n, self.n_features * self.n_legs, 1, 1)
        y = self.net(enn.GeometricTensor(fibre, self.in_type)).tensor
        y = y.reshape(n, JOINT_TORQUES, self.orbits, self.order).permute(0, 3, 2, 1)
        return y.reshape(n, self.n_legs, JOINT_TORQUES)


def build(dims: ModelDims, fields: int = 104, layers: int = 3, order: int = 0) -> E2cnnMLP:
    """`fields` regular fields per hidden layer (104: on hexa, about sdnn's parameter count),
    `layers` hidden layers, the cyclic group C_order (0: as many rotations as legs)."""
    n_legs, n_features = dims.shape("x")
    return E2cnnMLP(n_legs, n_features, order, fields, layers)
