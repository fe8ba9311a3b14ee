/* mrpt_fog test support: run a check in a forked child (a crash, a hang or an allocation limit
 * then ends the child, not the test program) and read how it ended. */
#pragma once

#include <sys/wait.h>
#include <unistd.h>

namespace fogtest
{
/** Runs body() in a child process and returns its exit code: body's return value, or
 * 100 + the signal that ended the child (a crash, or SIGALRM after an ::alarm() in body).
 * body must not return into the test framework: the child leaves by _exit. */
template <class Body>
int exitCodeInChild(Body&& body)
{
	const pid_t pid = ::fork();
	if (pid == 0) ::_exit(body());
	int status = 0;
	::waitpid(pid, &status, 0);
	return WIFEXITED(status) ? WEXITSTATUS(status) : 100 + WTERMSIG(status);
}
}  // namespace fogtest
