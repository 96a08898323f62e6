//! The deployment manifests of foveal: Kubernetes (`kubernetes/`: the server as a Deployment and
//! Service, the study as an indexed Job and its merge) and Slurm (`slurm/`: the study as a job
//! array). This crate holds no code; its tests decode every manifest strictly against the
//! Kubernetes API types and check that the manifests agree with each other and with the
//! binaries' flags, so that a manifest that would be refused by a cluster fails CI instead.
