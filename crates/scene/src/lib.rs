//! The scene file format (TOML, format 1): exact parsing and validation into typed bodies and motions
