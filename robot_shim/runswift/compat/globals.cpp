// Globals their walk files read, defined in their files we do not build (soccer.cpp).

/// Their kinematics asks whether it runs off the robot (their offline tools): it runs as on
/// the robot, as in their motion thread.
bool offNao = false;
