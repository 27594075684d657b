"""The whole-body controller: the QP, the leg kinematics, and its compiled kernel."""
