@echo off
rem Starts the KSE workbench. Needs a Java 21+ runtime: %JAVA_HOME%, or javaw on the PATH.
rem Arguments are passed on (e.g. -data <workspace> skips the workspace selection);
rem KSE_JAVA_OPTS adds options for the Java VM.
setlocal
set "HERE=%~dp0"
set "JAVA=javaw"
if defined JAVA_HOME set "JAVA=%JAVA_HOME%\bin\javaw"
set "LAUNCHER="
for %%f in ("%HERE%plugins\org.eclipse.equinox.launcher_*.jar") do set "LAUNCHER=%%f"
if not defined LAUNCHER (
  echo kse-workbench: no equinox launcher under %HERE%plugins 1>&2
  exit /b 2
)
start "KSE" "%JAVA%" -Xss16m %KSE_JAVA_OPTS% -jar "%LAUNCHER%" -name KSE %*
