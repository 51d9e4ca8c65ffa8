@echo off
rem Starts the KSE workbench. Needs a Java 21+ runtime: JAVA_HOME, or java on the PATH.
rem Arguments are passed on (e.g. -data <workspace> skips the workspace selection);
rem KSE_JAVA_OPTS adds options for the Java VM.
rem Why it cannot start also goes to a message box (a double-clicked script's console closes at
rem once) and to kse-workbench.log beside it, which each start overwrites so that it stays small.
rem Paths are expanded outside ( ) blocks: "C:\Program Files (x86)\..." would end a block early.
setlocal EnableExtensions DisableDelayedExpansion
set "HERE=%~dp0"

set "LOG=%HERE%kse-workbench.log"
copy /y /b nul "%LOG%" >nul 2>&1 && goto :find
rem an installation under Program Files is read-only for users
set "LOG=%TEMP%\kse-workbench.log"
copy /y /b nul "%LOG%" >nul 2>&1 && goto :find
set "LOG=nul"

:find
set "JAVA="
if not defined JAVA_HOME goto :path
set "JAVA_HOME=%JAVA_HOME:"=%"
set "FROM=JAVA_HOME is '%JAVA_HOME%'"
set "JAVA=%JAVA_HOME%\bin\java.exe"
if exist "%JAVA%" goto :version
set "MSG=needs Java 21 or newer and found none: %FROM%, which has no bin\java.exe; set JAVA_HOME to a Java 21+ installation"
goto :refuse

:path
set "FROM=JAVA_HOME is not set"
for /f "delims=" %%J in ('where java 2^>nul') do if not defined JAVA set "JAVA=%%J"
if defined JAVA goto :version
set "MSG=needs Java 21 or newer and found none: %FROM% and there is no java on the PATH; install Java 21+ and set JAVA_HOME to it"
goto :refuse

:version
rem for /f hands the command to cmd /c, which strips one pair of quotes: the added escaped pair
set "VERSION="
for /f "tokens=2 delims== " %%V in ('^""%JAVA%" -XshowSettings:properties -version 2^>^&1 ^| findstr /l /c:"java.specification.version"^"') do set "VERSION=%%V"
set "MAJOR="
for /f "delims=." %%M in ("%VERSION%") do set "MAJOR=%%M"
if not defined MAJOR goto :unreadable
rem set /a turns anything but a plain number into something else
set "NUMBER="
set /a "NUMBER=MAJOR" >nul 2>&1
if not "%NUMBER%"=="%MAJOR%" goto :unreadable
if %MAJOR% LSS 21 goto :old

rem javaw has no console, so the one of this script closes
for %%J in ("%JAVA%") do set "JAVAW=%%~dpJjavaw.exe"
if not exist "%JAVAW%" set "JAVAW=%JAVA%"
set "LAUNCHER="
for %%L in ("%HERE%plugins\org.eclipse.equinox.launcher_*.jar") do set "LAUNCHER=%%~fL"
if defined LAUNCHER goto :start
set "MSG=no Equinox launcher under '%HERE%plugins': the installation is incomplete"
goto :refuse

:start
rem Guice (inside Xtext) still uses sun.misc.Unsafe, which Java 24+ warns about at every start
set "QUIET="
if %MAJOR% GEQ 24 set "QUIET=--sun-misc-unsafe-memory-access=allow"
rem Class data sharing: the JVM keeps the classes a start loads in an archive per user and Java
rem version (made when the workbench first exits) and maps it at the next start
set "CDS="
set "ARCHIVE="
if not defined LOCALAPPDATA goto :launch
if not exist "%LOCALAPPDATA%\KSE\" mkdir "%LOCALAPPDATA%\KSE" >nul 2>&1
if not exist "%LOCALAPPDATA%\KSE\" goto :launch
set "CDS=-XX:+AutoCreateSharedArchive"
set "ARCHIVE=-XX:SharedArchiveFile=%LOCALAPPDATA%\KSE\workbench-java%MAJOR%.jsa"

:launch
set "MSG=starts '%JAVAW%' (Java %VERSION%)"
call :log
if defined ARCHIVE goto :launch_cds
start "KSE" "%JAVAW%" -Xss16m %QUIET% -splash:"%HERE%kse-splash.png" %KSE_JAVA_OPTS% -jar "%LAUNCHER%" -name KSE %* || goto :failed
exit /b 0

:launch_cds
start "KSE" "%JAVAW%" -Xss16m %QUIET% %CDS% "%ARCHIVE%" -splash:"%HERE%kse-splash.png" %KSE_JAVA_OPTS% -jar "%LAUNCHER%" -name KSE %* || goto :failed
exit /b 0

:failed
set "MSG=could not start '%JAVAW%' (Java %VERSION%)"
goto :refuse

:unreadable
set "MSG=needs Java 21 or newer and could not read the version of '%JAVA%' (%FROM%); set JAVA_HOME to a Java 21+ installation"
goto :refuse

:old
set "MSG=needs Java 21 or newer and found Java %VERSION% at '%JAVA%' (%FROM%); set JAVA_HOME to a Java 21+ installation"
goto :refuse

rem MSG holds the reason; delayed expansion prints it whatever characters the paths hold
:refuse
call :log
setlocal EnableDelayedExpansion
set "KSE_MESSAGE=kse-workbench: !MSG!"
if /i not "!LOG!"=="nul" set "KSE_MESSAGE=!KSE_MESSAGE! (also in !LOG!)"
>&2 echo(!KSE_MESSAGE!
rem the text reaches PowerShell through the environment, so quotes in it cannot break the command
powershell -NoProfile -NonInteractive -Command "$ErrorActionPreference = 'Stop'; try { Add-Type -AssemblyName PresentationFramework; [void][System.Windows.MessageBox]::Show($env:KSE_MESSAGE, 'KSE workbench', [System.Windows.MessageBoxButton]::OK, [System.Windows.MessageBoxImage]::Error) } catch { exit 1 }" >nul 2>&1 || msg "%USERNAME%" !KSE_MESSAGE! >nul 2>&1
exit /b 2

:log
setlocal EnableDelayedExpansion
>>"!LOG!" echo(!DATE! !TIME! !MSG!
endlocal
exit /b 0
