// A user module that happens to be called material(): an ordinary module, not metadata.
module material(color) { echo(user_material = color); children(); }
