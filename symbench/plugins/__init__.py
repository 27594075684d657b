"""Built-in plugins, registered through the `symbench` entry-point group like any other."""
