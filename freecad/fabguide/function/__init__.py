"""Works-like prototypes (thesis ch. 4): parts of cuboids, joints, configurations and the functional
relationships a Mechanism keeps satisfied by solving on recompute."""
