"""A dataset on disk: Parquet trajectories, named columns, validated metadata, SHA-256
per file and the content hash."""
