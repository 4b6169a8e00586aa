// Nothing: the dependency-rule project is configured, never built.
