"""External robot logs in and out: the import manifest, what is derived from a log,
and export back to plain files."""
